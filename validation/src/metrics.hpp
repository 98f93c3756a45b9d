// SPDX-License-Identifier: MIT
#pragma once

#include "engine.hpp"
#include "scenario.hpp"

#include <glm/vec2.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace e2d::validation {

/// A tagged body at one instant.
struct Sample {
    glm::vec2 position{0.0f};
    float angle = 0.0f;
    glm::vec2 velocity{0.0f};
};

/// Everything a run records, one entry per instant: index 0 is the initial state, index k the
/// state after k steps (time k * timeStep).
struct Recording {
    float timeStep = 1.0f / 60.0f;
    float settle = 0.0f;                               ///< seconds before timing starts
    std::map<std::string, std::vector<Sample>> tagged; ///< per tag, every instant (first body)
    /// Per tag, the bodies after the first that carry the same tag, each every instant: a
    /// check on a tag judges every body that has it.
    std::map<std::string, std::vector<std::vector<Sample>>> moreTagged;
    std::vector<float> kineticEnergy; ///< J, dynamic bodies
    std::vector<glm::vec2> momentum;  ///< kg m/s, dynamic bodies
    std::vector<float> maxSpeed;      ///< m/s, fastest dynamic body
    /// m, per instant: the largest joint error, over the revolute and weld joints the distance
    /// between their two anchors, over wheel joints the distance of B's anchor off the axis
    /// through A's anchor (the axis turning with body A), over rigid distance joints
    /// |length - rest length|; empty when the scene has none of these.
    std::vector<float> jointError;
    std::vector<float> penetration; ///< m, deepest contact
    std::vector<bool> allAsleep;    ///< every dynamic body asleep
    std::vector<double> stepMs;     ///< wall time of each step

    [[nodiscard]] int instants() const { return static_cast<int>(kineticEnergy.size()); }
    [[nodiscard]] float time(int instant) const { return static_cast<float>(instant) * timeStep; }
    /// The instant closest to `t` seconds, clamped to the recording.
    [[nodiscard]] int instantAt(float t) const;
};

/// Feeds a Recording from an engine. record() is called once before the first step and once
/// after each step.
class Recorder {
public:
    Recorder(const scenes::SceneDesc& scene, float settle);
    void record(const Engine& engine, double stepMs);
    [[nodiscard]] const Recording& recording() const { return rec_; }
    [[nodiscard]] Recording take() { return std::move(rec_); }

private:
    struct Tagged {
        std::string tag;
        int body;  // index in the scene
        int extra; // -1: the tag's first body (Recording::tagged); else its index in moreTagged
    };
    std::vector<Tagged> tags_;
    std::vector<BodyState> states_;
    struct MeasuredJoint {
        std::size_t index; // in SceneDesc::joints
        float rest;        // rigid distance joint: the length it holds; < 0: a point joint
        // Wheel joint: body A's index and starting angle, the axis in world axes at the start;
        // bodyA < 0 for the other kinds.
        int bodyA = -1;
        float angleA = 0.0f;
        glm::vec2 axis{0.0f};
    };
    std::vector<MeasuredJoint> joints_;
    std::vector<std::pair<glm::vec2, glm::vec2>> anchors_;
    Recording rec_;
};

/// Summary numbers of a run (see validation/README.md, "Metrics").
struct Metrics {
    double msMedian = 0.0;       ///< median ms per step after `settle`
    double msP95 = 0.0;          ///< 95th percentile ms per step after `settle`
    float maxPenetration = 0.0f; ///< deepest contact after `settle`, metres
    float maxSpeed = 0.0f;       ///< fastest dynamic body over the whole run, m/s
    float finalKineticEnergy = 0.0f;
    std::optional<float> topDrift;    ///< |x_end - x_start| of the body tagged "top", metres
    std::optional<bool> standing;     ///< top body within one half-size of its start
    std::optional<float> timeToSleep; ///< first time every dynamic body was asleep, seconds
};

[[nodiscard]] Metrics summarize(const Recording& rec, const scenes::SceneDesc& scene);

/// Median and 95th percentile (nearest rank) of `values`; {0, 0} when empty.
[[nodiscard]] std::pair<double, double> medianAndP95(std::vector<double> values);

} // namespace e2d::validation
