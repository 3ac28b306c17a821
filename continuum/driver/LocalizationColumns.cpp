#include "continuum/driver/LocalizationColumns.h"

namespace geocomp::continuum {

std::vector<ExtraColumn> localization_columns(const LocalizationColumnsOptions &options)
{
  std::vector<ExtraColumn> columns{
    {"localization_q", "1", options.q_description},
    {"localization_onset_time", "s", "program time of the first q <= 0 (-1: not yet)"}};
  if (options.onset_point)
    for (const char *axis : {"x", "y", "z"})
      columns.push_back({std::string("localization_") + axis, "m", std::string("onset point, ") + axis});
  for (const char *axis : {"x", "y", "z"})
    columns.push_back({std::string("localization_n") + axis, "1", std::string("band normal at onset, ") + axis});
  return columns;
}

} // namespace geocomp::continuum
