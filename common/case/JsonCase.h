#pragma once
// A JSON case file as the equivalent .prm text, so that both syntaxes reach deal.II's
// ParameterHandler the same way and get the same messages naming the parameter.
//
// Why it exists: ParameterHandler's own JSON reader (and Boost.PropertyTree's, used here
// before) builds the document recursively: 100 000 nested brackets overflow the stack.
// nlohmann-json's SAX parser keeps its nesting on the heap; the handler here writes each
// object as a `subsection`, each scalar as a `set` line, refuses arrays, null, nesting
// deeper than input_limits::max_json_depth and keys or values that .prm syntax cannot
// carry (a newline, a '#' that would start a comment, a '=' in a key, a final '\' that
// would continue the line), naming the entry.
#include <string>

namespace geocomp {

/// The .prm text of a JSON case; throws CaseError(path, entry or "(file)", ...).
std::string json_to_prm(const std::string &json, const std::string &path);

} // namespace geocomp
