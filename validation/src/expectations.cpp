// SPDX-License-Identifier: MIT
#include "expectations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace e2d::validation {

double bounceApex(double restitution, double height) { return restitution * restitution * height; }

double slideDistance(double g, double theta, double mu, double t) {
    const double a = g * (std::sin(theta) - mu * std::cos(theta));
    return a > 0.0 ? 0.5 * a * t * t : 0.0;
}

double stoppingDistance(double v, double mu, double g) { return v * v / (2.0 * mu * g); }

double slidingPosition(double v, double mu, double g, double t) {
    const double stop = v / (mu * g);
    const double s = std::min(t, stop);
    return v * s - 0.5 * mu * g * s * s;
}

double rollingDistance(double g, double theta, double t) {
    // A solid disc has I = m r^2 / 2, so a = g sin / (1 + I / (m r^2)) = (2/3) g sin.
    return 0.5 * (2.0 / 3.0) * g * std::sin(theta) * t * t;
}

Impact1D impact1D(double m1, double v1, double m2, double v2, double e) {
    // Momentum conservation plus Newton's law of restitution: v2' - v1' = -e (v2 - v1).
    const double p = m1 * v1 + m2 * v2;
    const double m = m1 + m2;
    return {(p + m2 * e * (v2 - v1)) / m, (p + m1 * e * (v1 - v2)) / m};
}

namespace {

double length(glm::vec2 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y); }

std::string fmt(double v) {
    std::ostringstream out;
    out.precision(4);
    out << v;
    return out.str();
}

const std::vector<Sample>& track(const Recording& rec, const std::string& tag) {
    static const std::vector<Sample> kEmpty;
    auto it = rec.tagged.find(tag);
    return it == rec.tagged.end() ? kEmpty : it->second;
}

// First instant at which the body's vertical velocity rose instead of falling under gravity by
// more than a tenth of g dt: the first impact. -1 if there was none.
int firstImpact(const std::vector<Sample>& s, float gravity, float dt) {
    for (std::size_t k = 1; k < s.size(); ++k) {
        if (s[k].velocity.y > s[k - 1].velocity.y + 0.1f * gravity * dt) {
            return static_cast<int>(k);
        }
    }
    return -1;
}

// Distance along a slope of angle theta: engines that push a resting body out along the
// normal first (Box2D's skin) are not charged for that.
double alongSlope(glm::vec2 d, float theta) {
    return std::abs(double(d.x) * std::cos(theta) + double(d.y) * std::sin(theta));
}

// Distance travelled along the initial velocity's direction by instant k.
double alongLaunch(const std::vector<Sample>& s, int k) {
    const glm::vec2 v = s.front().velocity;
    const double speed = length(v);
    const glm::vec2 d = s[static_cast<std::size_t>(k)].position - s.front().position;
    return speed > 0.0 ? (double(d.x) * v.x + double(d.y) * v.y) / speed : length(d);
}

struct Apexes {
    std::vector<int> instants; // instants of the apexes after each bounce
};

// Apexes after bounces: an apex is an instant where vy turns from > 0 to <= 0.
Apexes apexes(const std::vector<Sample>& s, int from) {
    Apexes a;
    for (std::size_t k = static_cast<std::size_t>(std::max(from, 1)); k < s.size(); ++k) {
        if (s[k - 1].velocity.y > 0.0f && s[k].velocity.y <= 0.0f) {
            a.instants.push_back(s[k].position.y >= s[k - 1].position.y ? static_cast<int>(k)
                                                                        : static_cast<int>(k) - 1);
        }
    }
    return a;
}

} // namespace

namespace {

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// The first instant at which the body's state or one of the run's summed quantities the check
// reads is not finite, or -1. Comparisons with NaN are false and std::max skips it, so a check
// left to itself could pass on a blown-up run.
int firstNonFinite(const Check& c, const Recording& rec, const std::vector<Sample>& s) {
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (!finite(s[k].position) || !finite(s[k].velocity) || !std::isfinite(s[k].angle)) {
            return static_cast<int>(k);
        }
    }
    for (int k = 0; k < rec.instants(); ++k) {
        const auto i = static_cast<std::size_t>(k);
        const bool bad =
            (c.kind == CheckKind::MaxSpeed && !std::isfinite(rec.maxSpeed[i])) ||
            (c.kind == CheckKind::MaxPenetration && !std::isfinite(rec.penetration[i])) ||
            (c.kind == CheckKind::Momentum && !finite(rec.momentum[i])) ||
            (c.kind == CheckKind::KineticEnergy && !std::isfinite(rec.kineticEnergy[i])) ||
            (c.kind == CheckKind::JointError && i < rec.jointError.size() &&
             !std::isfinite(rec.jointError[i]));
        if (bad) {
            return k;
        }
    }
    return -1;
}

// Rotation from the start at every instant, unwrapped (e2d reports angles in (-pi, pi], Box2D
// accumulates them): each step's change taken as the shortest turn.
std::vector<double> turns(const std::vector<Sample>& s) {
    std::vector<double> out;
    out.reserve(s.size());
    double total = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (k > 0) {
            double d = double(s[k].angle) - double(s[k - 1].angle);
            d -= 2.0 * std::numbers::pi * std::round(d / (2.0 * std::numbers::pi));
            total += d;
        }
        out.push_back(total);
    }
    return out;
}

// The times at which the body's x velocity turns from negative to non-negative (its leftmost
// points), interpolated between instants: one per period of a swing.
std::vector<double> leftTurns(const std::vector<Sample>& s, float dt) {
    std::vector<double> out;
    for (std::size_t k = 1; k < s.size(); ++k) {
        const double v0 = s[k - 1].velocity.x;
        const double v1 = s[k].velocity.x;
        if (v0 < 0.0 && v1 >= 0.0) {
            out.push_back((double(k - 1) + v0 / (v0 - v1)) * dt);
        }
    }
    return out;
}

// How far the body got from its start by instant k: along `direction`, or in any direction.
double moved(const std::vector<Sample>& s, int k, glm::vec2 direction) {
    if (s.empty()) {
        return 0.0;
    }
    const glm::vec2 d = s[static_cast<std::size_t>(k)].position - s.front().position;
    return direction == glm::vec2(0.0f) ? length(d)
                                        : double(d.x) * direction.x + double(d.y) * direction.y;
}

CheckResult evaluateOn(const Check& c, const Recording& rec, float gravity,
                       const std::vector<Sample>& s);

// evaluateOn with the non-finite guard.
CheckResult evaluateGuarded(const Check& c, const Recording& rec, float gravity,
                            const std::vector<Sample>& s) {
    CheckResult r = evaluateOn(c, rec, gravity, s);
    const int bad = firstNonFinite(c, rec, s);
    if (bad >= 0 || !std::isfinite(r.measured) || !std::isfinite(r.error)) {
        r.passed = false;
        r.error = std::numeric_limits<double>::infinity();
        r.detail = (bad >= 0 ? "non-finite state at t = " + fmt(rec.time(bad)) + " s"
                             : std::string("non-finite measurement")) +
                   (r.detail.empty() ? "" : "; " + r.detail);
    }
    return r;
}

// Which of two results of one check on different bodies is worse: a failure, then the larger
// error against the tolerance.
bool worse(const CheckResult& a, const CheckResult& b) {
    if (a.passed != b.passed) {
        return !a.passed;
    }
    const double ra = a.tolerance > 0.0 ? a.error / a.tolerance : a.error;
    const double rb = b.tolerance > 0.0 ? b.error / b.tolerance : b.error;
    return ra > rb || (std::isnan(ra) && !std::isnan(rb));
}

} // namespace

CheckResult evaluate(const Check& c, const Recording& rec, float gravity) {
    CheckResult r = evaluateGuarded(c, rec, gravity, track(rec, c.body));
    auto more = rec.moreTagged.find(c.body);
    if (c.body.empty() || more == rec.moreTagged.end() || more->second.empty()) {
        return r;
    }
    // Every body with the tag is judged; the worst one speaks for the check.
    const std::size_t count = more->second.size() + 1;
    std::size_t worstIndex = 0;
    for (std::size_t i = 0; i < more->second.size(); ++i) {
        CheckResult other = evaluateGuarded(c, rec, gravity, more->second[i]);
        if (worse(other, r)) {
            r = std::move(other);
            worstIndex = i + 1;
        }
    }
    r.detail = "worst of " + std::to_string(count) + " bodies tagged " + c.body + ": body " +
               std::to_string(worstIndex + 1) + (r.detail.empty() ? "" : "; " + r.detail);
    return r;
}

CheckResult evaluateFinite(const Check& c, const Recording& rec, float gravity) {
    return evaluateOn(c, rec, gravity, track(rec, c.body));
}

namespace {

CheckResult evaluateOn(const Check& c, const Recording& rec, float gravity,
                       const std::vector<Sample>& s) {
    CheckResult r;
    r.kind = checkKindName(c.kind);
    r.body = c.body;
    r.tolerance = c.tolerance;
    const int last = rec.instants() - 1;
    switch (c.kind) {
    case CheckKind::Standing: {
        const Sample& a = s.front();
        const Sample& b = s.back();
        r.quantity = "horizontal drift of the top body, m";
        r.expected = 0.0;
        r.measured = std::abs(b.position.x - a.position.x);
        r.error = r.measured;
        r.passed = r.error <= c.tolerance && b.position.y >= c.minY;
        r.detail = "final y " + fmt(b.position.y) + (b.position.y >= c.minY ? " >= " : " < ") +
                   "minY " + fmt(c.minY);
        break;
    }
    case CheckKind::MaxPenetration: {
        r.quantity = "deepest contact after settling, m";
        float deepest = 0.0f;
        for (int k = rec.instantAt(rec.settle); k <= last; ++k) {
            deepest = std::max(deepest, rec.penetration[static_cast<std::size_t>(k)]);
        }
        r.expected = c.limit;
        r.measured = deepest;
        r.tolerance = c.limit;
        r.error = deepest;
        r.passed = deepest <= c.limit;
        break;
    }
    case CheckKind::MaxSpeed: {
        double fastest = 0.0;
        if (c.body.empty()) {
            r.quantity = "fastest body over the run, m/s";
            fastest = *std::max_element(rec.maxSpeed.begin(), rec.maxSpeed.end());
        } else { // a NaN in the body's state fails the check (firstNonFinite())
            r.quantity = "fastest speed of \"" + c.body + "\" over the run, m/s";
            for (const Sample& sample : s) {
                fastest = std::max(fastest, length(sample.velocity));
            }
        }
        r.expected = c.limit;
        r.measured = fastest;
        r.tolerance = c.limit;
        r.error = fastest;
        r.passed = fastest <= c.limit;
        break;
    }
    case CheckKind::BounceHeight: {
        r.quantity = "first rebound apex above rest, m";
        r.expected = bounceApex(c.restitution, c.height);
        const int impact = firstImpact(s, gravity, rec.timeStep);
        double apex = 0.0;
        if (impact >= 0) {
            const Apexes a = apexes(s, impact);
            if (!a.instants.empty()) {
                apex = s[static_cast<std::size_t>(a.instants.front())].position.y - c.restY;
            } else {
                // No rebound at all: the ball stayed down; measure how high it sat.
                apex = s.back().position.y - c.restY;
            }
            r.detail = "impact at t = " + fmt(rec.time(impact)) + " s";
        } else {
            r.detail = "the ball never hit the floor";
            apex = s.back().position.y - c.restY;
        }
        r.measured = apex;
        r.error = std::abs(r.measured - r.expected);
        r.passed = impact >= 0 && r.error <= c.tolerance;
        break;
    }
    case CheckKind::SlideDistance:
    case CheckKind::RollingDistance: {
        const bool sliding = c.kind == CheckKind::SlideDistance;
        r.quantity = sliding ? "distance slid at t, m" : "distance rolled at t, m";
        r.expected = sliding ? slideDistance(gravity, c.slopeAngle, c.friction, c.time)
                             : rollingDistance(gravity, c.slopeAngle, c.time);
        const int k = rec.instantAt(c.time);
        r.measured =
            alongSlope(s[static_cast<std::size_t>(k)].position - s.front().position, c.slopeAngle);
        r.error = std::abs(r.measured - r.expected);
        r.passed = r.error <= c.tolerance;
        r.detail = "at t = " + fmt(rec.time(k)) + " s";
        break;
    }
    case CheckKind::StoppingDistance: {
        r.quantity = "distance slid until rest, m";
        r.expected = stoppingDistance(c.speed, c.friction, gravity);
        r.measured = alongLaunch(s, static_cast<int>(s.size()) - 1);
        r.error = std::abs(r.measured - r.expected);
        r.passed = r.error <= c.tolerance && length(s.back().velocity) < 0.01;
        r.detail = "final speed " + fmt(length(s.back().velocity)) + " m/s";
        break;
    }
    case CheckKind::Momentum: {
        r.quantity = "|P_end - P_start| / max(|P_start|, 1 kg m/s)";
        const glm::vec2 p0 = rec.momentum.front();
        const glm::vec2 p1 = rec.momentum.back();
        r.expected = 0.0;
        r.measured = length(p1 - p0) / std::max(length(p0), 1.0);
        r.error = r.measured;
        r.passed = r.error <= c.tolerance;
        r.detail = "P_start (" + fmt(p0.x) + ", " + fmt(p0.y) + "), P_end (" + fmt(p1.x) + ", " +
                   fmt(p1.y) + ")";
        break;
    }
    case CheckKind::KineticEnergy: {
        r.quantity = "KE_end / KE_start";
        const double e0 = rec.kineticEnergy.front();
        const double e1 = rec.kineticEnergy.back();
        r.expected = c.ratio;
        r.measured = e0 > 0.0 ? e1 / e0 : 0.0;
        r.error = std::abs(r.measured - r.expected);
        r.passed = e0 > 0.0 && r.error <= c.tolerance;
        r.detail = "KE_start " + fmt(e0) + " J, KE_end " + fmt(e1) + " J";
        break;
    }
    case CheckKind::Velocity: {
        r.quantity = "|v_end - v_expected|, m/s";
        const glm::vec2 v = s.back().velocity;
        r.expected = 0.0;
        r.measured = length(v - c.velocity);
        r.error = r.measured;
        r.passed = r.error <= c.tolerance;
        r.detail = "v_end (" + fmt(v.x) + ", " + fmt(v.y) + "), expected (" + fmt(c.velocity.x) +
                   ", " + fmt(c.velocity.y) + ")";
        break;
    }
    case CheckKind::Bounds: {
        r.quantity = "largest excursion outside the box, m";
        double worst = 0.0;
        for (const Sample& x : s) {
            const glm::vec2 p = x.position;
            worst = std::max({worst, double(c.lower.x - p.x), double(p.x - c.upper.x),
                              double(c.lower.y - p.y), double(p.y - c.upper.y)});
        }
        r.measured = worst;
        r.error = worst;
        r.passed = worst <= 0.0;
        break;
    }
    case CheckKind::Sleep: {
        r.quantity = "time until every body sleeps, s";
        r.expected = c.time;
        r.tolerance = c.time;
        int k = 0;
        while (k <= last && !rec.allAsleep[static_cast<std::size_t>(k)]) {
            ++k;
        }
        r.passed = k <= last && rec.time(k) <= c.time;
        r.measured = k <= last ? rec.time(k) : -1.0;
        r.error = k <= last ? rec.time(k) : 2.0 * c.time;
        r.detail = k <= last ? "" : "never slept";
        break;
    }
    case CheckKind::Turn: {
        r.quantity = "rotation from the start, rad";
        const std::vector<double> turn = turns(s);
        double largest = 0.0;
        bool finiteTurns = true;
        for (double t : turn) {
            finiteTurns = finiteTurns && std::isfinite(t);
            largest = std::max(largest, std::abs(t));
        }
        const double final = turn.empty() ? 0.0 : std::abs(turn.back());
        r.passed = finiteTurns;
        r.error = 0.0;
        r.measured = final;
        if (c.minTurn) {
            // Judged by the final rotation: e.g. a domino that must have fallen.
            r.expected = *c.minTurn;
            r.tolerance = *c.minTurn;
            r.error = std::max(0.0, *c.minTurn - final);
            r.passed = r.passed && final >= *c.minTurn;
            r.detail = "final rotation " + fmt(final) + " rad";
        }
        if (c.maxTurn) {
            // Judged by the largest rotation at any instant: e.g. a box that must stay level.
            r.measured = largest;
            r.expected = *c.maxTurn;
            r.tolerance = *c.maxTurn;
            r.error = std::max(r.error, largest);
            r.passed = r.passed && largest <= *c.maxTurn;
            r.detail = (c.minTurn ? r.detail + ", " : std::string()) + "largest rotation " +
                       fmt(largest) + " rad";
        }
        if (!finiteTurns) {
            r.measured = std::numeric_limits<double>::quiet_NaN();
        }
        break;
    }
    case CheckKind::JointError: {
        r.quantity = "largest joint error over the run, m";
        float worst = 0.0f;
        for (float e : rec.jointError) {
            worst = std::max(worst, e);
        }
        r.expected = c.limit;
        r.measured = worst;
        r.tolerance = c.limit;
        r.error = worst;
        r.passed = !rec.jointError.empty() && worst <= c.limit;
        r.detail = rec.jointError.empty() ? "no joint measured" : "";
        break;
    }
    case CheckKind::Period: {
        r.quantity = "mean period of the swing, s";
        r.expected = c.period;
        r.tolerance = c.tolerance;
        const std::vector<double> t = leftTurns(s, rec.timeStep);
        if (t.size() < 2) {
            r.measured = 0.0;
            r.error = c.period;
            r.passed = false;
            r.detail = "fewer than two swings";
            break;
        }
        r.measured = (t.back() - t.front()) / double(t.size() - 1);
        r.error = std::abs(r.measured - c.period);
        r.passed = r.error <= c.tolerance;
        r.detail = std::to_string(t.size() - 1) + " periods";
        break;
    }
    case CheckKind::Moves: {
        r.quantity = c.direction == glm::vec2(0.0f)
                         ? "distance from the start, m"
                         : "distance from the start along the direction, m";
        r.expected = c.distance;
        r.tolerance = c.distance;
        r.measured = moved(s, static_cast<int>(s.size()) - 1, c.direction);
        r.error = std::max(0.0, c.distance - r.measured);
        r.passed = r.measured >= c.distance;
        break;
    }
    }
    return r;
}

} // namespace

Series seriesFor(const Check& c, const Recording& rec, float gravity, int stride) {
    Series out;
    stride = std::max(stride, 1);
    if (c.kind == CheckKind::JointError) {
        out.name = "largest joint error; dashed: limit";
        out.unit = std::string("m");
        for (std::size_t k = 0; k < rec.jointError.size(); k += std::size_t(stride)) {
            out.t.push_back(rec.time(static_cast<int>(k)));
            out.measured.push_back(rec.jointError[k]);
            out.expected.push_back(c.limit);
        }
        return out;
    }
    const std::vector<Sample>& s = track(rec, c.body);
    if (s.empty()) {
        return out;
    }
    auto sample = [&](auto&& measured, auto&& expected) {
        for (int k = 0; k < static_cast<int>(s.size()); k += stride) {
            out.t.push_back(rec.time(k));
            out.measured.push_back(static_cast<float>(measured(k)));
            out.expected.push_back(static_cast<float>(expected(k)));
        }
    };
    auto distance = [&](int k) {
        return alongSlope(s[static_cast<std::size_t>(k)].position - s.front().position,
                          c.slopeAngle);
    };
    switch (c.kind) {
    case CheckKind::BounceHeight: {
        out.name = "height of " + c.body + " above rest; dashed: e^2n h at each apex";
        // A temporary: GCC 12 at -O2 warns falsely (-Wrestrict) on assign(const char*).
        out.unit = std::string("m");
        // The analytic envelope: e^(2n) h after the n-th bounce, as a staircase that steps at
        // each measured impact.
        const int impact = firstImpact(s, gravity, rec.timeStep);
        std::vector<int> impacts;
        for (std::size_t k = 1; k < s.size(); ++k) {
            if (impact >= 0 && static_cast<int>(k) >= impact && s[k - 1].velocity.y < 0.0f &&
                s[k].velocity.y > s[k - 1].velocity.y + 0.1f * gravity * rec.timeStep) {
                impacts.push_back(static_cast<int>(k));
            }
        }
        sample([&](int k) { return s[static_cast<std::size_t>(k)].position.y - c.restY; },
               [&](int k) {
                   int n = 0;
                   for (int i : impacts) {
                       n += i <= k ? 1 : 0;
                   }
                   return c.height * std::pow(double(c.restitution), 2.0 * n);
               });
        break;
    }
    case CheckKind::SlideDistance:
        out.name = "distance slid by " + c.body + "; dashed: 1/2 g (sin - mu cos) t^2";
        out.unit = std::string("m");
        sample(distance, [&](int k) {
            return slideDistance(gravity, c.slopeAngle, c.friction, rec.time(k));
        });
        break;
    case CheckKind::RollingDistance:
        out.name = "distance rolled by " + c.body + "; dashed: 1/3 g sin t^2";
        out.unit = std::string("m");
        sample(distance,
               [&](int k) { return rollingDistance(gravity, c.slopeAngle, rec.time(k)); });
        break;
    case CheckKind::StoppingDistance:
        out.name = "distance slid by " + c.body + "; dashed: v t - 1/2 mu g t^2";
        out.unit = std::string("m");
        sample([&](int k) { return alongLaunch(s, k); },
               [&](int k) { return slidingPosition(c.speed, c.friction, gravity, rec.time(k)); });
        break;
    case CheckKind::Turn: {
        out.name = "rotation of " + c.body + "; dashed: " +
                   std::string(c.maxTurn ? "largest rotation allowed" : "least final rotation");
        out.unit = std::string("rad");
        const std::vector<double> turn = turns(s);
        const double bound = c.maxTurn ? *c.maxTurn : c.minTurn.value_or(0.0f);
        sample([&](int k) { return std::abs(turn[static_cast<std::size_t>(k)]); },
               [&](int) { return bound; });
        break;
    }
    case CheckKind::JointError:
        break;
    case CheckKind::Period: {
        out.name =
            "x of " + c.body + " about its mean; dashed: the same swing at the expected period";
        out.unit = std::string("m");
        double mean = 0.0;
        for (const Sample& x : s) {
            mean += x.position.x;
        }
        mean /= double(s.size());
        const double amplitude = double(s.front().position.x) - mean;
        sample([&](int k) { return double(s[static_cast<std::size_t>(k)].position.x) - mean; },
               [&](int k) {
                   return amplitude * std::cos(2.0 * std::numbers::pi * rec.time(k) / c.period);
               });
        break;
    }
    case CheckKind::Moves:
        out.name = "distance of " + c.body + " from its start; dashed: least distance at the end";
        out.unit = std::string("m");
        sample([&](int k) { return moved(s, k, c.direction); }, [&](int) { return c.distance; });
        break;
    case CheckKind::Standing:
        out.name = "horizontal drift of " + c.body + "; dashed: tolerance";
        out.unit = std::string("m");
        sample(
            [&](int k) {
                return std::abs(s[static_cast<std::size_t>(k)].position.x - s.front().position.x);
            },
            [&](int) { return c.tolerance; });
        break;
    default:
        break;
    }
    return out;
}

} // namespace e2d::validation
