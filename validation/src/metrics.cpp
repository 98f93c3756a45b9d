// SPDX-License-Identifier: MIT
#include "metrics.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::validation {

int Recording::instantAt(float t) const {
    const int k = static_cast<int>(std::lround(t / timeStep));
    return std::clamp(k, 0, std::max(0, instants() - 1));
}

Recorder::Recorder(const scenes::SceneDesc& scene, float settle) {
    rec_.timeStep = scene.timeStep;
    rec_.settle = settle;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const std::string& tag = scene.bodies[i].tag;
        if (tag.empty()) {
            continue;
        }
        if (!rec_.tagged.contains(tag)) {
            rec_.tagged[tag] = {};
            tags_.push_back({tag, static_cast<int>(i), -1});
        } else {
            auto& more = rec_.moreTagged[tag];
            tags_.push_back({tag, static_cast<int>(i), static_cast<int>(more.size())});
            more.emplace_back();
        }
    }
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const scenes::JointDesc& j = scene.joints[i];
        if (j.kind == scenes::JointKind::Revolute || j.kind == scenes::JointKind::Weld) {
            joints_.push_back({i, -1.0f});
        } else if (j.kind == scenes::JointKind::Wheel) {
            joints_.push_back(
                {i, -1.0f, j.bodyA, scene.bodies[std::size_t(j.bodyA)].angle, j.axis});
        } else if (j.kind == scenes::JointKind::Distance && !j.enableSpring && !j.enableLimit) {
            const glm::vec2 d = j.anchorB - j.anchorA;
            joints_.push_back({i, j.length > 0.0f ? j.length : std::sqrt(d.x * d.x + d.y * d.y)});
        }
    }
}

void Recorder::record(const Engine& engine, double stepMs) {
    engine.readBodies(states_);
    float kinetic = 0.0f;
    glm::vec2 momentum{0.0f};
    float fastest = 0.0f;
    bool asleep = true;
    for (const BodyState& s : states_) {
        if (!s.dynamic) {
            continue;
        }
        const float v2 = s.velocity.x * s.velocity.x + s.velocity.y * s.velocity.y;
        kinetic += 0.5f * s.mass * v2 + 0.5f * s.inertia * s.angularVelocity * s.angularVelocity;
        momentum += s.mass * s.velocity;
        // A non-finite speed must reach the checks: std::max would drop a NaN.
        const float speed = std::sqrt(v2);
        fastest = std::isfinite(fastest) && !(speed <= fastest) ? speed : fastest;
        asleep = asleep && !s.awake;
    }
    rec_.kineticEnergy.push_back(kinetic);
    rec_.momentum.push_back(momentum);
    rec_.maxSpeed.push_back(fastest);
    rec_.penetration.push_back(engine.maxPenetration());
    rec_.allAsleep.push_back(asleep);
    if (!joints_.empty()) {
        engine.readJointAnchors(anchors_);
        float worst = 0.0f;
        for (const MeasuredJoint& j : joints_) {
            const auto& [a, b] = anchors_[j.index];
            const glm::vec2 d = b - a;
            float error = 0.0f;
            if (j.bodyA >= 0) {
                // Wheel: B's anchor off the axis, which turns with body A.
                const float turn = states_[static_cast<std::size_t>(j.bodyA)].angle - j.angleA;
                const float c = std::cos(turn);
                const float s = std::sin(turn);
                const glm::vec2 axis{c * j.axis.x - s * j.axis.y, s * j.axis.x + c * j.axis.y};
                error = std::abs(axis.x * d.y - axis.y * d.x);
            } else {
                const float gap = std::sqrt(d.x * d.x + d.y * d.y);
                error = j.rest < 0.0f ? gap : std::abs(gap - j.rest);
            }
            // As for speeds: a NaN must reach the check.
            worst = std::isfinite(worst) && !(error <= worst) ? error : worst;
        }
        rec_.jointError.push_back(worst);
    }
    if (rec_.kineticEnergy.size() > 1) {
        rec_.stepMs.push_back(stepMs);
    }
    for (const Tagged& t : tags_) {
        const BodyState& s = states_[static_cast<std::size_t>(t.body)];
        std::vector<Sample>& track =
            t.extra < 0 ? rec_.tagged[t.tag]
                        : rec_.moreTagged[t.tag][static_cast<std::size_t>(t.extra)];
        track.push_back({s.position, s.angle, s.velocity});
    }
}

std::pair<double, double> medianAndP95(std::vector<double> values) {
    if (values.empty()) {
        return {0.0, 0.0};
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    // Nearest rank: the smallest value with at least 95 % of the values at or below it.
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n)));
    return {median, values[std::max<std::size_t>(rank, 1) - 1]};
}

namespace {

// Half the height of a body's first shape: the scale at which "still standing" is judged.
float halfHeight(const scenes::BodyDesc& body) {
    if (body.shapes.empty()) {
        return 0.5f;
    }
    const scenes::ShapeDesc& s = body.shapes.front();
    switch (s.kind) {
    case scenes::ShapeKind::Box:
        return s.halfExtents.y;
    case scenes::ShapeKind::Circle:
    case scenes::ShapeKind::Capsule:
        return s.radius;
    default:
        return 0.5f;
    }
}

} // namespace

Metrics summarize(const Recording& rec, const scenes::SceneDesc& scene) {
    Metrics m;
    const int first = rec.instantAt(rec.settle);
    std::vector<double> timed;
    for (int k = std::max(first, 1); k < rec.instants(); ++k) {
        timed.push_back(rec.stepMs[static_cast<std::size_t>(k - 1)]);
    }
    std::tie(m.msMedian, m.msP95) = medianAndP95(std::move(timed));
    for (int k = 0; k < rec.instants(); ++k) {
        m.maxSpeed = std::max(m.maxSpeed, rec.maxSpeed[static_cast<std::size_t>(k)]);
        if (k >= first) {
            m.maxPenetration =
                std::max(m.maxPenetration, rec.penetration[static_cast<std::size_t>(k)]);
        }
        if (!m.timeToSleep && rec.allAsleep[static_cast<std::size_t>(k)]) {
            m.timeToSleep = rec.time(k);
        }
    }
    if (!rec.kineticEnergy.empty()) {
        m.finalKineticEnergy = rec.kineticEnergy.back();
    }
    if (auto it = rec.tagged.find("top"); it != rec.tagged.end() && !it->second.empty()) {
        const Sample& start = it->second.front();
        const Sample& end = it->second.back();
        m.topDrift = std::abs(end.position.x - start.position.x);
        float h = 0.5f;
        for (const scenes::BodyDesc& b : scene.bodies) {
            if (b.tag == "top") {
                h = halfHeight(b);
                break;
            }
        }
        m.standing = *m.topDrift < h && end.position.y > start.position.y - h;
    }
    return m;
}

} // namespace e2d::validation
