// SPDX-License-Identifier: MIT
#include "ratio_reporter.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace e2d::bench {

RatioReporter::RatioReporter(std::string baseline, std::vector<std::string> engineOrder,
                             RatioTargets targets)
    : baseline_(std::move(baseline)), engines_(std::move(engineOrder)),
      targets_(std::move(targets)) {}

void RatioReporter::ReportRuns(const std::vector<Run>& reports) {
    std::vector<Run> runs = reports;
    for (Run& run : runs) {
        // With repetitions, the median stands for the benchmark; single runs stand for themselves.
        const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
        if (run.error_occurred || (run.run_type != Run::RT_Iteration && !median) ||
            (run.run_type == Run::RT_Iteration && run.repetitions > 1)) {
            continue;
        }
        const std::string name = run.run_name.function_name;
        const auto last = name.rfind('/');
        if (last == std::string::npos) {
            continue;
        }
        const std::string caseName = name.substr(0, last);
        const std::string engine = name.substr(last + 1);
        const auto items = run.counters.find("items_per_second");
        if (items == run.counters.end() || items->second.value <= 0.0) {
            continue;
        }
        // items_per_second is already a rate over real time; invert it to ns per item.
        const double ns = 1e9 / items->second.value;
        // Cases in the order their benchmarks were registered, whatever order they ran in (with
        // random interleaving, any).
        auto [rank, added] = caseRank_.try_emplace(caseName, run.family_index);
        if (!added) {
            rank->second = std::min(rank->second, run.family_index);
        }
        nsPerItem_[caseName][engine] = ns;
        run.counters["ns_per_item"] = benchmark::Counter(ns);
        const auto& byEngine = nsPerItem_[caseName];
        const auto base = byEngine.find(baseline_);
        if (engine != baseline_ && base != byEngine.end() && base->second > 0.0) {
            run.counters["vs_" + baseline_] = benchmark::Counter(ns / base->second);
        }
    }
    ConsoleReporter::ReportRuns(runs);
}

std::string RatioReporter::markdownTable(const std::string& unit, double nsPerUnit) const {
    std::ostringstream out;
    out << "| case |";
    for (const auto& e : engines_) {
        out << ' ' << e << " (" << unit << ") |";
    }
    for (const auto& e : engines_) {
        if (e != baseline_) {
            out << ' ' << e << " / " << baseline_ << " |";
        }
    }
    const bool targeted = !targets_.byCase.empty();
    if (targeted) {
        out << " target (" << targets_.engine << " / " << baseline_ << ") | meets |";
    }
    out << "\n|---|";
    for (std::size_t i = 0; i < 2 * engines_.size() - 1; ++i) {
        out << "---:|";
    }
    if (targeted) {
        out << "---:|:---:|";
    }
    out << '\n';
    char buf[64];
    std::vector<std::string> caseOrder;
    for (const auto& entry : caseRank_) {
        caseOrder.push_back(entry.first);
    }
    std::stable_sort(caseOrder.begin(), caseOrder.end(), [&](const auto& a, const auto& b) {
        return caseRank_.at(a) < caseRank_.at(b);
    });
    for (const auto& c : caseOrder) {
        const auto& byEngine = nsPerItem_.at(c);
        out << "| " << c << " |";
        for (const auto& e : engines_) {
            const auto it = byEngine.find(e);
            if (it == byEngine.end()) {
                out << " - |";
            } else {
                const double value = it->second / nsPerUnit;
                std::snprintf(buf, sizeof buf, value < 10.0 ? " %.3f |" : " %.1f |", value);
                out << buf;
            }
        }
        const auto base = byEngine.find(baseline_);
        for (const auto& e : engines_) {
            if (e == baseline_) {
                continue;
            }
            const auto it = byEngine.find(e);
            if (it == byEngine.end() || base == byEngine.end()) {
                out << " - |";
            } else {
                std::snprintf(buf, sizeof buf, " %.3f |", it->second / base->second);
                out << buf;
            }
        }
        if (targeted) {
            const auto target = targets_.byCase.find(c);
            const auto it = byEngine.find(targets_.engine);
            if (target == targets_.byCase.end()) {
                out << " - | - |";
            } else {
                std::snprintf(buf, sizeof buf, " %.2f |", target->second);
                out << buf;
                if (it == byEngine.end() || base == byEngine.end()) {
                    out << " - |";
                } else {
                    out << (it->second / base->second <= target->second ? " yes |" : " no |");
                }
            }
        }
        out << '\n';
    }
    return out.str();
}

std::string RatioReporter::takeTableFlag(int& argc, char** argv) {
    static constexpr const char* kFlag = "--e2d_table=";
    std::string path;
    int kept = 0;
    for (int i = 0; i < argc; ++i) {
        if (std::strncmp(argv[i], kFlag, std::strlen(kFlag)) == 0) {
            path = argv[i] + std::strlen(kFlag);
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    return path;
}

int runWithRatios(int argc, char** argv, const std::string& baseline,
                  const std::vector<std::string>& engineOrder, const std::string& unit,
                  double nsPerUnit, const std::string& appendix, const RatioTargets& targets) {
    const std::string tablePath = RatioReporter::takeTableFlag(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 2;
    }
    RatioReporter reporter(baseline, engineOrder, targets);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    const std::string table = reporter.markdownTable(unit, nsPerUnit) + appendix;
    std::printf("\n%s", table.c_str());
    if (!tablePath.empty()) {
        std::ofstream(tablePath) << table;
    }
    return 0;
}

} // namespace e2d::bench
