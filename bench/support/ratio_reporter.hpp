// SPDX-License-Identifier: MIT
#pragma once

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace e2d::bench {

/// Benchmarks are named "<group>/<case>/<engine>" and process `items` pairs or bodies per
/// iteration (SetItemsProcessed). This reporter prints as the console reporter does, adds a
/// counter `vs_<baseline>` (this engine's time per item over the baseline engine's, measured
/// earlier in the same run) and writes a Markdown table of ns per item and ratios.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    RatioReporter(std::string baseline, std::vector<std::string> engineOrder);

    void ReportRuns(const std::vector<Run>& reports) override;

    /// The table: one row per case, one column per engine, then ratios to the baseline. Times
    /// are ns per item divided by `nsPerUnit` (1e6 for ms).
    std::string markdownTable(const std::string& unit = "ns per pair",
                              double nsPerUnit = 1.0) const;

    /// Pulls `--e2d_table=PATH` out of argv (before benchmark::Initialize sees it).
    static std::string takeTableFlag(int& argc, char** argv);

private:
    std::string baseline_;
    std::vector<std::string> engines_;
    std::vector<std::string> caseOrder_;
    std::map<std::string, std::map<std::string, double>> nsPerItem_; // case -> engine -> ns
};

/// Runs the registered benchmarks with a RatioReporter and writes its table where
/// `--e2d_table=PATH` says (if given), followed by `appendix` (more Markdown, may be empty).
/// Times in the table are ns per item over `nsPerUnit`. Returns main's exit status.
int runWithRatios(int argc, char** argv, const std::string& baseline,
                  const std::vector<std::string>& engineOrder, const std::string& unit,
                  double nsPerUnit = 1.0, const std::string& appendix = {});

} // namespace e2d::bench
