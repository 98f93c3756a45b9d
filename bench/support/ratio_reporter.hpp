// SPDX-License-Identifier: MIT
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace e2d::bench {

/// The bar each case's ratio is held to: `engine`'s time per item over the baseline's, at or
/// below `byCase[case]` (case as in the table: "step/pyramid_10"). The table then shows a
/// `target` and a `meets` (yes/no) column; a case with no target shows "-" in both.
struct RatioTargets {
    std::string engine;
    std::map<std::string, double> byCase;
};

/// Benchmarks are named "<group>/<case>/<engine>" and process `items` pairs or bodies per
/// iteration (SetItemsProcessed). This reporter prints as the console reporter does, adds a
/// counter `vs_<baseline>` (this engine's time per item over the baseline engine's, measured
/// earlier in the same run; absent when the baseline's run came later) and writes a Markdown table of ns per item and ratios.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    RatioReporter(std::string baseline, std::vector<std::string> engineOrder,
                  RatioTargets targets = {});

    void ReportRuns(const std::vector<Run>& reports) override;

    /// The table: one row per case, one column per engine, then ratios to the baseline, to three
    /// decimals (a ratio at a two-decimal target shows which side it is on), and the target
    /// columns (see RatioTargets). Times are ns per item divided by `nsPerUnit` (1e6 for ms).
    std::string markdownTable(const std::string& unit = "ns per pair",
                              double nsPerUnit = 1.0) const;

    /// Pulls `--e2d_table=PATH` out of argv (before benchmark::Initialize sees it).
    static std::string takeTableFlag(int& argc, char** argv);

private:
    std::string baseline_;
    std::vector<std::string> engines_;
    RatioTargets targets_;
    std::map<std::string, std::int64_t> caseRank_; // case -> its first benchmark's family index
    std::map<std::string, std::map<std::string, double>> nsPerItem_; // case -> engine -> ns
};

/// Runs the registered benchmarks with a RatioReporter and writes its table where
/// `--e2d_table=PATH` says (if given), followed by `appendix` (more Markdown, may be empty).
/// Times in the table are ns per item over `nsPerUnit`; `targets` adds the target columns.
/// Returns main's exit status.
int runWithRatios(int argc, char** argv, const std::string& baseline,
                  const std::vector<std::string>& engineOrder, const std::string& unit,
                  double nsPerUnit = 1.0, const std::string& appendix = {},
                  const RatioTargets& targets = {});

} // namespace e2d::bench
