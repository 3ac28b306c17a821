#pragma once
// @sect3{Rate-sweep outputs: a TSV table, an SVG plot and a gnuplot script}
//
// Why: the sweep's result is one small table (rate, normalized strength, S1's fit, error,
// the inertia-free point value, run data). TSV is read by anything; the SVG plot is
// written directly (no plotting dependency) in the layout of S1's Figs. 5-6: log rate on
// x, normalized strength on y, the fit (14) or (15) as a line, kinetic runs as filled
// circles, kinetic-off runs as open squares; the gnuplot script redraws it from the TSV.
#include "continuum/dynamics/RateSweep.h"

#include <string>
#include <vector>

namespace geocomp::dynamics {

void write_rate_sweep_tsv(const std::string &path, const RateSweepSetup &setup, const std::vector<RateSweepRow> &rows);
void write_rate_sweep_svg(const std::string &path, const RateSweepSetup &setup, const std::vector<RateSweepRow> &rows);
/// A gnuplot script that plots `tsv_name` (relative to the script's folder) to SVG.
void write_rate_sweep_gnuplot(const std::string &path, const std::string &tsv_name, const RateSweepSetup &setup);

} // namespace geocomp::dynamics
