// SPDX-License-Identifier: MIT
#include <e2d/physics/solver_def.hpp>

#include <e2d/physics/constants.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::physics {

static_assert(kMaxContactRecycleDistance == kAabbMargin);

namespace {

[[noreturn]] void fail(const std::string& what) {
    throw core::Error("physics::World::World(): def.solver." + what);
}

void requireRange(const char* name, int value, int lo, int hi) {
    if (value < lo || value > hi) {
        fail(std::string(name) + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
             "], got " + std::to_string(value));
    }
}

void requirePositive(const char* name, float value) {
    if (!(std::isfinite(value) && value > 0.0f)) {
        fail(std::string(name) + " must be finite and > 0, got " + core::formatNumber(value));
    }
}

void requireNonNegative(const char* name, float value) {
    if (!(std::isfinite(value) && value >= 0.0f)) {
        fail(std::string(name) + " must be finite and >= 0, got " + core::formatNumber(value));
    }
}

void requireInterval(const char* name, float value, float lo, float hi) {
    if (!(std::isfinite(value) && value >= lo && value <= hi)) {
        fail(std::string(name) + " must be finite and in [" + core::formatNumber(lo) + ", " +
             core::formatNumber(hi) + "], got " + core::formatNumber(value));
    }
}

bool isRule(MixingRule rule) {
    auto r = static_cast<int>(rule);
    return r >= static_cast<int>(MixingRule::GeometricMean) &&
           r <= static_cast<int>(MixingRule::Multiply);
}

} // namespace

void validate(const SolverDef& def) {
    auto mode = static_cast<int>(def.mode);
    if (mode != static_cast<int>(SolverMode::SoftStep) &&
        mode != static_cast<int>(SolverMode::Classic)) {
        fail("mode must be SoftStep or Classic, got " + std::to_string(mode));
    }
    requireRange("subSteps", def.subSteps, 1, 64);
    requireRange("relaxIterations", def.relaxIterations, 0, 64);
    requireRange("velocityIterations", def.velocityIterations, 1, 256);
    requireRange("positionIterations", def.positionIterations, 0, 256);
    requireInterval("classicAllowedPenetration", def.classicAllowedPenetration, 0.0f,
                    kMaxClassicAllowedPenetration);
    requireInterval("classicPositionBias", def.classicPositionBias, 0.0f, 1.0f);
    requirePositive("contactHertz", def.contactHertz);
    requireNonNegative("contactDampingRatio", def.contactDampingRatio);
    requirePositive("jointHertz", def.jointHertz);
    requireNonNegative("jointDampingRatio", def.jointDampingRatio);
    requireRange("jointPositionIterations", def.jointPositionIterations, 0, 256);
    auto jointSolver = static_cast<int>(def.jointSolver);
    if (jointSolver != static_cast<int>(JointSolver::Soft) &&
        jointSolver != static_cast<int>(JointSolver::GaussSeidel) &&
        jointSolver != static_cast<int>(JointSolver::Direct)) {
        fail("jointSolver must be Soft, GaussSeidel or Direct, got " + std::to_string(jointSolver));
    }
    requirePositive("contactPushMaxSpeed", def.contactPushMaxSpeed);
    requireNonNegative("restitutionThreshold", def.restitutionThreshold);
    requirePositive("maxLinearSpeed", def.maxLinearSpeed);
    requireNonNegative("hitEventThreshold", def.hitEventThreshold);
    requireNonNegative("linearSleepTolerance", def.linearSleepTolerance);
    requireNonNegative("angularSleepTolerance", def.angularSleepTolerance);
    requirePositive("timeToSleep", def.timeToSleep);
    if (!isRule(def.frictionMixing)) {
        fail("frictionMixing is not a MixingRule, got " +
             std::to_string(static_cast<int>(def.frictionMixing)));
    }
    if (!isRule(def.restitutionMixing)) {
        fail("restitutionMixing is not a MixingRule, got " +
             std::to_string(static_cast<int>(def.restitutionMixing)));
    }
    requireInterval("contactRecycleDistance", def.contactRecycleDistance, 0.0f,
                    kMaxContactRecycleDistance);
}

float mix(MixingRule rule, float a, float b) {
    switch (rule) {
    case MixingRule::GeometricMean:
        return std::sqrt(a * b);
    case MixingRule::Average:
        return 0.5f * (a + b);
    case MixingRule::Min:
        return std::min(a, b);
    case MixingRule::Max:
        return std::max(a, b);
    case MixingRule::Multiply:
        return a * b;
    }
    return std::sqrt(a * b);
}

} // namespace e2d::physics
