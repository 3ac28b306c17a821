#pragma once
// @sect3{The DEM's specimen-to-specimen scatter as the yardstick of a difference}
//
// Why it exists: a continuum that misses the DEM's peak by 5 % has failed only if another
// specimen of the same granular material would not miss it by as much. The same loading
// program run on several specimens (seeds, store variants) gives, for every metric m of the
// report (metric_table: elastic limit, peak, softening, residual, dilatancy, ...), a band
//   [m_low, m_high] = [min_k m_k, max_k m_k]   over the specimens k,
// and a continuum engine's value v lies "within scatter" when
//   m_low - t |m|_max <= v <= m_high + t |m|_max,   t = 1e-6 (round-off, a band of one width),
// "outside" otherwise, "n/a" where the value or the band is not defined (no peak found).
#include "compare/Metrics.h"

#include <string>
#include <vector>

namespace geocomp::compare {

struct ScatterRow {
  std::string key, label, units; ///< as metric_table() names the metric
  double low = nan, high = nan;   ///< the band over the specimens (NaN: defined on none)
  std::vector<std::string> verdicts; ///< per judged engine: "within scatter", "outside", "n/a"
};

struct ScatterTable {
  std::vector<std::string> specimens; ///< the specimens' names (results files)
  std::vector<std::string> engines;   ///< the judged engines' labels
  std::vector<ScatterRow> rows;       ///< one per metric
};

/// The band of each metric over `specimens` (metric sets of the same program) and the verdict
/// of each engine of `judged`; `tolerance` is t above.
ScatterTable scatter_table(const std::vector<std::string> &names, const std::vector<MetricSet> &specimens,
                           const std::vector<std::string> &engines, const std::vector<MetricSet> &judged,
                           double tolerance = 1e-6);

} // namespace geocomp::compare
