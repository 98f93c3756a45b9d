// SPDX-License-Identifier: MIT
#include "cli.hpp"

#include "engine.hpp"
#include "plan.hpp"
#include "report.hpp"
#include "runner.hpp"
#include "scenario_parser.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <ostream>
#include <thread>

#ifndef E2D_VALIDATION_SCENARIOS_DIR
#define E2D_VALIDATION_SCENARIOS_DIR "validation/scenarios"
#endif

namespace e2d::validation {
namespace fs = std::filesystem;

namespace {

struct Options {
    bool all = false;
    bool quick = false;
    bool list = false;
    std::vector<std::string> scenarios;
    std::string out = "report";
    std::string dir = E2D_VALIDATION_SCENARIOS_DIR;
    std::string sweep; // empty: the mode's default
    std::vector<std::string> engines;
    bool noFeatures = false;
    int jobs = 0;
};

std::vector<fs::path> scenarioFiles(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.is_regular_file() && entry.path().extension() == ".json") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

fs::path resolve(const std::string& fileOrName, const fs::path& dir) {
    if (fs::is_regular_file(fileOrName)) {
        return fileOrName;
    }
    const fs::path named = dir / (fileOrName + ".json");
    if (fs::is_regular_file(named)) {
        return named;
    }
    throw ScenarioError(core::Diagnostic{core::Severity::Error,
                                         "--scenario " + fileOrName,
                                         0,
                                         0,
                                         {},
                                         "no such file, and no scenario of that name in " +
                                             dir.string() + " (see --list)"});
}

// Family order of the report, then names in natural order (stack_5 before stack_10).
void sortScenarios(std::vector<Scenario>& scenarios) {
    const std::vector<std::string> families{"stacking",     "friction", "restitution",
                                            "conservation", "joints",   "hard"};
    auto rank = [&](const Scenario& s) {
        return std::find(families.begin(), families.end(), s.family) - families.begin();
    };
    auto natural = [](const std::string& a, const std::string& b) {
        std::size_t i = 0;
        std::size_t j = 0;
        while (i < a.size() && j < b.size()) {
            if (std::isdigit(static_cast<unsigned char>(a[i])) != 0 &&
                std::isdigit(static_cast<unsigned char>(b[j])) != 0) {
                std::size_t ie = i;
                std::size_t je = j;
                while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie])) != 0) {
                    ++ie;
                }
                while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je])) != 0) {
                    ++je;
                }
                const std::string na = a.substr(i, ie - i);
                const std::string nb = b.substr(j, je - j);
                if (na.size() != nb.size()) {
                    return na.size() < nb.size();
                }
                if (na != nb) {
                    return na < nb;
                }
                i = ie;
                j = je;
            } else {
                if (a[i] != b[j]) {
                    return a[i] < b[j];
                }
                ++i;
                ++j;
            }
        }
        return a.size() - i < b.size() - j;
    };
    std::stable_sort(scenarios.begin(), scenarios.end(), [&](const Scenario& a, const Scenario& b) {
        return rank(a) != rank(b) ? rank(a) < rank(b) : natural(a.name, b.name);
    });
}

std::string joined(const std::vector<std::string>& args) {
    std::string s = "e2d-validate";
    for (const std::string& a : args) {
        s += " " + a;
    }
    return s;
}

} // namespace

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    Options o;
    CLI::App app{"e2d-validate: runs physics scenarios on e2d and Box2D 2.4 and reports speed "
                 "against error (report.json, report.html and a summary on stdout)."};
    app.name("e2d-validate");
    auto* all = app.add_flag("--all", o.all, "every scenario, full sweep and feature runs");
    auto* quick =
        app.add_flag("--quick", o.quick, "the quick subset (scenarios with \"quick\": true)");
    auto* scen =
        app.add_option("--scenario", o.scenarios,
                       "a scenario file or the name of one in --scenarios-dir (repeatable)");
    auto* list = app.add_flag("--list", o.list, "list the scenarios of --scenarios-dir and exit");
    all->excludes(quick)->excludes(scen)->excludes(list);
    quick->excludes(scen)->excludes(list);
    scen->excludes(list);
    app.add_option("--out", o.out, "directory the report is written to")->capture_default_str();
    app.add_option("--scenarios-dir", o.dir, "where scenario names are looked up")
        ->capture_default_str();
    app.add_option("--sweep", o.sweep,
                   "solver-effort sweep: none, quick or full (default: full for --all, quick "
                   "for --quick, none for --scenario)")
        ->check(CLI::IsMember({"none", "quick", "full"}));
    app.add_option("--engines", o.engines, "engines to run (default: every engine built)")
        ->delimiter(',');
    app.add_flag("--no-features", o.noFeatures, "skip the feature on/off runs");
    app.add_option("--jobs", o.jobs, "worker threads (default: all hardware threads)")
        ->check(CLI::Range(1, 256));

    std::vector<std::string> reversed(args.rbegin(), args.rend());
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        out << app.help();
        return kExitPassed;
    } catch (const CLI::ParseError& e) {
        err << "e2d-validate: " << e.what() << "\n"
            << "run e2d-validate --help for usage\n";
        return kExitBadInput;
    }
    if (!o.all && !o.quick && o.scenarios.empty() && !o.list) {
        err << "e2d-validate: give one of --all, --quick, --scenario FILE_OR_NAME or --list\n";
        return kExitBadInput;
    }
    const std::vector<std::string> available = availableEngines();
    if (o.engines.empty()) {
        o.engines = available;
    }
    for (const std::string& e : o.engines) {
        if (std::find(available.begin(), available.end(), e) == available.end()) {
            err << "e2d-validate: --engines: \"" << e << "\" is not built in (have:";
            for (const std::string& a : available) {
                err << " " << a;
            }
            err << ")\n";
            return kExitBadInput;
        }
    }

    std::vector<Scenario> scenarios;
    try {
        if (o.list || o.all || o.quick) {
            if (!fs::is_directory(o.dir)) {
                throw ScenarioError(core::Diagnostic{core::Severity::Error,
                                                     "--scenarios-dir " + o.dir,
                                                     0,
                                                     0,
                                                     {},
                                                     "not a directory"});
            }
            for (const fs::path& file : scenarioFiles(o.dir)) {
                Scenario s = loadScenario(file);
                if (o.list || o.all || s.quick) {
                    scenarios.push_back(std::move(s));
                }
            }
        } else {
            for (const std::string& name : o.scenarios) {
                scenarios.push_back(loadScenario(resolve(name, o.dir)));
            }
        }
    } catch (const std::exception& e) {
        err << "e2d-validate: " << e.what() << "\n";
        return kExitBadInput;
    }
    sortScenarios(scenarios);
    if (o.list) {
        for (const Scenario& s : scenarios) {
            out << s.name << "  [" << s.family << (s.quick ? ", quick" : "") << "]  "
                << s.description << "\n";
        }
        return kExitPassed;
    }
    if (scenarios.empty()) {
        err << "e2d-validate: no scenarios to run\n";
        return kExitBadInput;
    }

    const std::string sweepName = !o.sweep.empty() ? o.sweep
                                  : o.all          ? "full"
                                  : o.quick        ? "quick"
                                                   : "none";
    const SweepLevel level = sweepName == "full"    ? SweepLevel::Full
                             : sweepName == "quick" ? SweepLevel::Quick
                                                    : SweepLevel::None;
    const bool features = !o.noFeatures && (o.all || o.quick);
    const std::vector<RunSpec> plan = makePlan(scenarios, o.engines, level, features);
    const int threads =
        o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));

    err << "e2d-validate: " << scenarios.size() << " scenarios, " << plan.size() << " runs on "
        << threads << " threads\n";
    const auto start = std::chrono::steady_clock::now();
    int lastPercent = -1;
    // Runs left per scenario, to say when each scenario is done.
    std::vector<int> left(scenarios.size(), 0);
    for (const RunSpec& spec : plan) {
        ++left[static_cast<std::size_t>(spec.scenario)];
    }
    std::vector<int> baselineRuns(scenarios.size(), 0);
    std::vector<int> baselinePassed(scenarios.size(), 0);
    std::mutex errMutex; // the workers' step progress and the finished-run lines share err
    Report report;
    const auto stepProgress = [&](const RunSpec& spec, int step, int steps, double seconds) {
        const std::lock_guard lock(errMutex);
        err << "  ... " << scenarios[static_cast<std::size_t>(spec.scenario)].name << " / "
            << spec.config.family() << " " << spec.variant << ": "
            << (step == 0 ? std::string("world built")
                          : "step " + std::to_string(step) + " of " + std::to_string(steps) + " (" +
                                std::to_string(100 * static_cast<long long>(step) / steps) + "%)")
            << " after " << static_cast<int>(seconds) << " s\n";
    };
    report.runs = runPlan(
        scenarios, plan, threads,
        [&](int done, int total, const RunResult& r) {
            const std::lock_guard lock(errMutex);
            const auto si = static_cast<std::size_t>(r.spec.scenario);
            if (r.spec.role == RunRole::Baseline) {
                ++baselineRuns[si];
                baselinePassed[si] += r.passed ? 1 : 0;
            }
            if (--left[si] == 0) {
                err << "scenario " << scenarios[si].name << " done: " << baselinePassed[si]
                    << " of " << baselineRuns[si] << " baseline runs pass\n";
            }
            const int percent = 100 * done / total;
            if (percent / 5 != lastPercent / 5 || r.seconds > 5.0 || done == total) {
                lastPercent = percent;
                const double elapsed =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                err << "[" << done << "/" << total << " " << percent << "% "
                    << static_cast<int>(elapsed) << " s] "
                    << scenarios[static_cast<std::size_t>(r.spec.scenario)].name << " / "
                    << r.spec.config.family() << " " << r.spec.variant << ": " << r.seconds
                    << " s\n";
            }
        },
        stepProgress);
    report.scenarios = std::move(scenarios);
    report.env = collectEnvironment();
    report.env.threads = threads;
    report.env.command = joined(args);
    report.env.sweep = sweepName;
    report.env.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    try {
        fs::create_directories(o.out);
        std::ofstream json(fs::path(o.out) / "report.json");
        json << reportToJson(report).dump(1) << "\n";
        std::ofstream html(fs::path(o.out) / "report.html");
        html << reportToHtml(report);
        if (!json || !html) {
            throw std::runtime_error("cannot write the report to " + o.out);
        }
    } catch (const std::exception& e) {
        err << "e2d-validate: --out " << o.out << ": " << e.what() << "\n";
        return kExitBadInput;
    }
    out << reportSummary(report);
    out << "report: " << (fs::absolute(o.out) / "report.html").string() << " and report.json\n";
    return exitStatus(report);
}

} // namespace e2d::validation
