#include "compare/Scatter.h"

#include <algorithm>
#include <cmath>

namespace geocomp::compare {

ScatterTable scatter_table(const std::vector<std::string> &names, const std::vector<MetricSet> &specimens,
                           const std::vector<std::string> &engines, const std::vector<MetricSet> &judged,
                           double tolerance)
{
  ScatterTable out{names, engines, {}};
  std::vector<std::vector<MetricValue>> bands, values;
  for (const MetricSet &m : specimens)
    bands.push_back(metric_table(m));
  for (const MetricSet &m : judged)
    values.push_back(metric_table(m));
  // Keys and units are fixed; labels name the curve's axes, as the specimens' do.
  const std::vector<MetricValue> rows =
    metric_table(!specimens.empty() ? specimens.front() : !judged.empty() ? judged.front() : MetricSet{});
  for (std::size_t r = 0; r < rows.size(); ++r) {
    ScatterRow row;
    row.key = rows[r].key;
    row.label = rows[r].label;
    row.units = rows[r].units;
    for (const auto &b : bands)
      if (std::isfinite(b[r].value)) {
        row.low = std::isfinite(row.low) ? std::min(row.low, b[r].value) : b[r].value;
        row.high = std::isfinite(row.high) ? std::max(row.high, b[r].value) : b[r].value;
      }
    const double slack = tolerance * std::max(std::abs(row.low), std::abs(row.high));
    for (const auto &v : values) {
      const double x = v[r].value;
      if (!std::isfinite(x) || !std::isfinite(row.low))
        row.verdicts.push_back("n/a");
      else
        row.verdicts.push_back(x >= row.low - slack && x <= row.high + slack ? "within scatter" : "outside");
    }
    out.rows.push_back(std::move(row));
  }
  return out;
}

} // namespace geocomp::compare
