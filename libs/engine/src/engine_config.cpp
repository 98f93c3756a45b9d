// SPDX-License-Identifier: MIT
#include <e2d/engine/engine_config.hpp>

#include <e2d/core/error_text.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>

#include <algorithm>
#include <system_error>

namespace e2d::engine {

namespace {

using core::ConfigBounds;

// Every key of the file, bound to its field of `c`.
core::ConfigReader readerFor(EngineConfig& c) {
    constexpr ConfigBounds kPositive = ConfigBounds::above(0.0);
    constexpr ConfigBounds kNonNegative = ConfigBounds::atLeast(0.0);
    constexpr ConfigBounds kAtLeastOne = ConfigBounds::atLeast(1.0);
    core::ConfigReader r;
    // SCENE
    r.add("firstScene", c.firstScene);
    // DISPLAY
    r.add("referenceWindowWidth", c.referenceWindowWidth, kAtLeastOne);
    r.add("referenceWindowHeight", c.referenceWindowHeight, kAtLeastOne);
    r.add("windowWidth", c.windowWidth, kAtLeastOne);
    r.add("windowHeight", c.windowHeight, kAtLeastOne);
    r.add("screenFitMode", c.screenFitMode,
          {{"expand", render::ScreenFit::Expand},
           {"widthFit", render::ScreenFit::WidthFit},
           {"heightFit", render::ScreenFit::HeightFit},
           {"bestFit", render::ScreenFit::BestFit}});
    r.add("windowMode", c.windowMode,
          {{"windowed", render::WindowMode::Windowed},
           {"fullscreen", render::WindowMode::Fullscreen},
           {"borderless", render::WindowMode::Borderless}});
    r.add("windowTitle", c.windowTitle);
    r.add("textureFilteringMode", c.textureFilteringMode,
          {{"nearest", render::TextureFilter::Nearest}, {"linear", render::TextureFilter::Linear}});
    r.add("maxCameraDepth", c.maxCameraDepth, kPositive);
    r.add("vsync", c.vsync);
    r.add("msaaSamples", c.msaaSamples, ConfigBounds{0.0, 16.0});
    // TEXT
    r.add("fontSize", c.fontSize, kAtLeastOne);
    // PHYSICS
    r.add("gravityX", c.gravityX);
    r.add("gravityY", c.gravityY);
    r.add("fixedTimestep", c.fixedTimestep, ConfigBounds{0.0, 1.0, true});
    r.add("collisionResolutionSteps", c.collisionResolutionSteps, kAtLeastOne);
    r.add("physicsSolver", c.physicsSolver,
          {{"softStep", physics::SolverMode::SoftStep}, {"classic", physics::SolverMode::Classic}});
    r.add("allowedPenetration", c.allowedPenetration, kNonNegative);
    r.add("penetrationBiasFactor", c.penetrationBiasFactor, ConfigBounds{0.0, 1.0});
    r.add("minRigidbodySpeed", c.minRigidbodySpeed, kNonNegative);
    r.add("physicsWorkers", c.physicsWorkers,
          ConfigBounds{1.0, static_cast<double>(physics::kMaxWorkers)});
    r.add("unitsPerMetre", c.unitsPerMetre, kPositive);
    // SOUND
    r.add("minAttenuationDistance", c.minAttenuationDistance, kNonNegative);
    r.add("maxAttenuationDistance", c.maxAttenuationDistance, kNonNegative);
    r.add("minPanningDistance", c.minPanningDistance, kNonNegative);
    r.add("maxPanningDistance", c.maxPanningDistance, kNonNegative);
    r.add("masterGain", c.masterGain, kNonNegative);
    r.add("voiceCount", c.voiceCount, ConfigBounds{1.0, 1024.0});
    // INPUT
    r.add("bindingsFile", c.bindingsFile);
    r.add("keyRepeat", c.keyRepeat);
    // LOOP
    r.add("maxStepsPerFrame", c.maxStepsPerFrame, kAtLeastOne);
    r.add("randomSeed", c.randomSeed);
    r.add("maxFrameTime", c.maxFrameTime, ConfigBounds{0.0, 10.0, true});
    // DEBUG
    r.add("debugDraw", c.debugDraw);
    r.add("debugDrawKey", c.debugDrawKey);
    r.add("printProfile", c.printProfile);
    r.add("showProfile", c.showProfile);
    r.add("profileKey", c.profileKey);
    return r;
}

// A min above its max is blamed on whichever of the two was written last; both go back to
// their defaults, which are consistent.
void checkOrder(EngineConfig& c, core::ConfigReport& report, std::string_view file,
                std::string_view minKey, float EngineConfig::*minField, std::string_view maxKey,
                float EngineConfig::*maxField) {
    if (c.*minField <= c.*maxField) {
        return;
    }
    if (report.lineOf(maxKey) > report.lineOf(minKey)) {
        report.error(file, maxKey,
                     "must be >= " + std::string(minKey) + " (" + core::formatNumber(c.*minField) +
                         "), got " + core::formatNumber(c.*maxField));
    } else {
        report.error(file, minKey,
                     "must be <= " + std::string(maxKey) + " (" + core::formatNumber(c.*maxField) +
                         "), got " + core::formatNumber(c.*minField));
    }
    const EngineConfig defaults;
    c.*minField = defaults.*minField;
    c.*maxField = defaults.*maxField;
}

} // namespace

// The PHYSICS keys are SI already: the World runs in metres, and the PhysicsSystem converts
// what the components see by unitsPerMetre.
physics::WorldDef makeWorldDef(const EngineConfig& config) {
    physics::WorldDef def;
    def.gravity = {config.gravityX, config.gravityY};
    def.solver.mode = config.physicsSolver;
    def.solver.subSteps = std::min(config.collisionResolutionSteps, 64);
    def.solver.velocityIterations = std::min(config.collisionResolutionSteps, 256);
    def.solver.linearSleepTolerance = config.minRigidbodySpeed;
    def.workerCount = config.physicsWorkers;
    // Both keys are already checked by the reader (>= 0, and [0, 1]); only the physics' upper
    // bound on the overlap is left, a cap like the sub-steps' above rather than an error.
    def.solver.classicAllowedPenetration =
        std::min(config.allowedPenetration, physics::kMaxClassicAllowedPenetration);
    def.solver.classicPositionBias = config.penetrationBiasFactor;
    return def;
}

namespace {

// The checks across keys.
EngineConfigResult finish(EngineConfigResult result, core::ConfigReport report,
                          std::string_view sourceName) {
    EngineConfig& c = result.config;
    checkOrder(c, report, sourceName, "minAttenuationDistance",
               &EngineConfig::minAttenuationDistance, "maxAttenuationDistance",
               &EngineConfig::maxAttenuationDistance);
    checkOrder(c, report, sourceName, "minPanningDistance", &EngineConfig::minPanningDistance,
               "maxPanningDistance", &EngineConfig::maxPanningDistance);
    result.diagnostics = std::move(report.diagnostics);
    return result;
}

} // namespace

EngineConfigResult parseEngineConfig(std::string_view text, std::string_view sourceName) {
    EngineConfigResult result;
    core::ConfigReport report = readerFor(result.config).read(text, sourceName);
    return finish(std::move(result), std::move(report), sourceName);
}

EngineConfigResult loadEngineConfig(const std::filesystem::path& path, bool required) {
    EngineConfigResult result;
    std::error_code ec;
    const core::TextFile file = core::readTextFile(path);
    if (!file.ok()) {
        const std::string message = "cannot read the configuration file (" + file.error + ")";
        if (required) {
            result.diagnostics.error(core::printable(path.string()), 0, message);
        } else {
            result.diagnostics.warning(core::printable(path.string()), 0,
                                       message + ", using the defaults");
        }
        result.config.assetRoot = std::filesystem::current_path(ec);
        return result;
    }
    core::ConfigReport report = readerFor(result.config).read(file.text, path.string());
    result.config.file = path;
    std::filesystem::path root = path.parent_path();
    if (root.empty()) {
        root = std::filesystem::current_path(ec);
    }
    result.config.assetRoot = root;
    return finish(std::move(result), std::move(report), path.string());
}

} // namespace e2d::engine
