// libFuzzer target for the case-file reader: any input must either parse or be refused
// with a CaseError; a crash, a sanitizer report or any other exception is a bug.
#include "common/case/CaseParameters.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  if (size == 0)
    return 0;
  // The first byte picks the syntax, the rest is the file.
  const std::string name = (data[0] & 1) ? "fuzz.json" : "fuzz.prm";
  const std::string text(reinterpret_cast<const char *>(data + 1), size - 1);
  try {
    geocomp::parse_case(text, name);
  } catch (const geocomp::CaseError &) {
  }
  return 0;
}
