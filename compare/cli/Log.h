#pragma once
// The command line's messages, through spdlog (Debian's libspdlog-dev), at three levels a
// user chooses with --quiet / --verbose: what a run says it is doing (info, stdout: "dem:
// 88 samples ...", "report: ..."), warnings and errors (stderr, "warning: ..." / "error:
// ..."), and details for --verbose (stderr, "debug: ..."). The progress display (Progress.h)
// is shown at the normal and verbose levels only. --quiet keeps warnings and errors alone.
// A command's product - check's summary, compare's JSON, print-parameters - is not a
// message: it goes to stdout whatever the level.
#include <string>

namespace geocomp::cli::log {

enum class Verbosity { quiet, normal, verbose };

void set_verbosity(Verbosity v);
Verbosity verbosity();
/// Whether the progress display draws (not under --quiet).
bool progress_shown();

void info(const std::string &text);
void warning(const std::string &text);
void error(const std::string &text);
void debug(const std::string &text);

} // namespace geocomp::cli::log
