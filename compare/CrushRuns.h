#pragma once
// @sect3{Crush runs read back from their results folder}
//
// Why it exists: S2's figures compare runs, not one run. Fig. 7 overlays the gradation of
// three replacement modes, Fig. 3 the fragment sizes of ten seeds of the single-particle
// test. Each `geocomp crush` run writes <case>_summary.tsv (key<TAB>value: title, program,
// breakage mode, cut point, counts, wall seconds), <case>_curve.tsv, <case>_gradation.tsv,
// <case>_fragments.tsv and, for uniaxial runs, <case>_polar_{seated,peak,final}.svg
// (dem/program/CrushPrograms.h); this reads every run of a folder into one record, so the
// report (CrushReport.h) draws from what was run and nothing else. Units as in the files:
// mm, kPa, N, percent.
//
// Fig. 3's quantity (S2 sec. 1.2): the size distribution of the fragments of a
// single-particle test, here per seed (the run column of _fragments.tsv) as the percentage
// of that seed's fragments by number in each size bin, with its mean relative size d/D.
// For the cube mode without d_M the mean of d/D over a parent's eight children is
// prod_axes (x^{1/3} + (1-x)^{1/3}) / 2 with x = U^p (S2 eqs. (1)-(2), U uniform, p the cut
// power), so its expectation is (E[(x^{1/3} + (1-x)^{1/3}) / 2])^3 with
// E[x^q] = 1 / (1 + p q) and E[(1-x)^q] = B(1/p, q+1) / p (Beta function): 0.4219 (plain),
// 0.3743 (squared), 0.3309 (cubed).
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace geocomp::compare {

/// A TSV table with one header line (CrushPrograms.h's Table as written).
struct CrushTable
{
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// The index of column `name`; throws std::runtime_error naming `file` when absent.
  std::size_t column(const std::string& name, const std::filesystem::path& file) const;
};

struct CrushRun
{
  std::string name;                            ///< the case's stem
  std::map<std::string, std::string> summary;  ///< every key of <case>_summary.tsv
  std::string title, program, breakage_mode, cut_point;
  CrushTable curve, gradation, fragments;      ///< fragments empty when the file is missing
  std::vector<std::filesystem::path> roses;    ///< <case>_polar_*.svg found beside it
  bool single() const { return program == "single particle"; }
  /// A summary value as a number, `fallback` when the key is missing or not a number.
  double number(const std::string& key, double fallback = 0.0) const;
};

/// One run from its summary file (<dir>/<case>_summary.tsv) and the tables beside it.
/// Throws std::runtime_error naming the file and what is missing.
CrushRun read_crush_run(const std::filesystem::path& summary);

/// Every run in `dir` (each <case>_summary.tsv with a program key), sorted by name.
std::vector<CrushRun> read_crush_runs(const std::filesystem::path& dir);

/// Fig. 3 for one seed of a single-particle run.
struct SeedFragments
{
  int run = 0;                           ///< the seed's repetition number
  std::size_t fragments = 0;
  double mean_relative_size = 0.0;       ///< mean child d / parent D
  std::vector<double> percent;           ///< by number, bin k covers [k bin, (k+1) bin) mm
};

/// Fig. 3's distribution per seed of a single-particle run's fragments, bins of `bin_mm`.
std::vector<SeedFragments> fragments_by_seed(const CrushRun& run, double bin_mm);

/// The expectation of the mean d/D over a parent's children in cube mode without d_M,
/// for cut power p = 1, 2, 3 (closed form above).
double expected_mean_relative_size(int cut_power);

}  // namespace geocomp::compare
