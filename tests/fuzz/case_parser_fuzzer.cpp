// libFuzzer target for the case-file reader, one syntax per binary (GEOCOMP_FUZZ_EXTENSION:
// ".prm" or ".json", tests/fuzz/CMakeLists.txt): any input must either parse or be refused
// with a CaseError; a crash, a stack overflow, a sanitizer report, a hang or any other
// exception is a bug. `include` lines are followed as in a case (relative to the working
// directory here): the reader's limits and checks apply to what they name.
#include "compare/case/CaseDescription.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char *>(data), size);
  try {
    geocomp::parse_case(text, std::string("fuzz") + GEOCOMP_FUZZ_EXTENSION);
  } catch (const geocomp::CaseError &) {
  }
  return 0;
}
