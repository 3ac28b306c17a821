#pragma once
// Text from a user (a file name, a title) inside a gnuplot script.
//
// Why it exists: gnuplot runs whatever its script says, `system("...")` and back-quoted
// commands included. A name written into the script between single quotes must not be
// able to close them: in a single-quoted gnuplot string a quote is doubled, back quotes and
// '@' macros are not expanded, and a line break (which would end the command) is written
// as a space.
#include <string>

namespace geocomp::compare {

/// `text` as a single-quoted gnuplot string, quotes included.
std::string gnuplot_quoted(const std::string &text);

} // namespace geocomp::compare
