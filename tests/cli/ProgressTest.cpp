// The progress display (issue 30): an unloading branch keeps the overall bar where the main
// path left it and shows its own progress and ETA (the bar used to fall to 0 % with an
// unknown ETA in every branch); specimen preparation shows each phase with its fraction.
#include "compare/cli/Progress.h"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>

using namespace geocomp;
using namespace geocomp::cli;

namespace {
/// Everything written to std::cerr while `body` runs.
template <class Body> std::string captured(Body body)
{
  std::ostringstream out;
  std::streambuf *old = std::cerr.rdbuf(out.rdbuf());
  body();
  std::cerr.rdbuf(old);
  return out.str();
}

RunProgress at(int branch, double fraction)
{
  RunProgress p;
  p.stage = 0;
  p.stage_count = 1;
  p.branch = branch;
  p.stage_fraction = fraction;
  return p;
}
} // namespace

TEST(Progress, AnUnloadingBranchKeepsTheMainPathsShareAndShowsItsOwn)
{
  ProgressPrinter printer("dem", 0.0, false); // log lines, one per call
  const std::string out = captured([&] {
    printer(at(0, 0.4));
    printer(at(1, 0.25));
    printer(at(1, 0.5));
    printer(at(0, 0.45));
  });
  std::istringstream lines(out);
  std::string main1, branch1, branch2, main2;
  std::getline(lines, main1);
  std::getline(lines, branch1);
  std::getline(lines, branch2);
  std::getline(lines, main2);
  EXPECT_EQ(main1.rfind("dem: 40% stage 1/1 t=", 0), 0u) << main1;
  EXPECT_EQ(branch1.rfind("dem: 40% stage 1/1 branch 1 25% (ETA ", 0), 0u) << branch1;
  EXPECT_EQ(branch2.rfind("dem: 40% stage 1/1 branch 1 50% (ETA ", 0), 0u) << branch2;
  EXPECT_EQ(branch2.find("ETA --:--"), std::string::npos) << branch2;
  EXPECT_EQ(main2.rfind("dem: 45% stage 1/1 t=", 0), 0u) << main2;
}

TEST(Progress, PreparationPhasesShowTheirFractionAndEndAtOneHundred)
{
  PhasePrinter printer("dem", 1e9, false);
  const std::string out = captured([&] {
    printer("growth", 0.01, 0.25);
    printer("growth", 0.02, 0.5); // within the log interval: no line
    printer("growth", 0.04, 1.0);
    printer("consolidation", 0.001, 0.3);
  });
  EXPECT_NE(out.find("dem: preparing: growth [#####...............]  25%, 0.01 s of DEM time"), std::string::npos)
    << out;
  EXPECT_EQ(out.find(" 50%"), std::string::npos) << out;
  EXPECT_NE(out.find("dem: preparing: growth [####################] 100%, 0.04 s of DEM time"), std::string::npos)
    << out;
  EXPECT_NE(out.find("dem: preparing: consolidation [######..............]  30%"), std::string::npos) << out;
}
