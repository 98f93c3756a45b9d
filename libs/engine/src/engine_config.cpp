// SPDX-License-Identifier: MIT
#include <e2d/engine/engine_config.hpp>

#include <algorithm>
#include <system_error>

namespace e2d::engine {

physics::WorldDef makeWorldDef(const core::Config& config) {
    const auto metres = [&config](double units) { return static_cast<float>(units / config.unitsPerMetre); };
    physics::WorldDef def;
    def.gravity = {metres(config.gravityX), metres(config.gravityY)};
    def.solver.mode = config.physicsSolver == core::PhysicsSolver::Classic ? physics::SolverMode::Classic
                                                                            : physics::SolverMode::SoftStep;
    def.solver.subSteps = std::min(config.collisionResolutionSteps, 64);
    def.solver.velocityIterations = std::min(config.collisionResolutionSteps, 256);
    def.solver.linearSleepTolerance = metres(config.minRigidbodySpeed);
    // Both keys are already checked by core (>= 0, and [0, 1]); only the physics' upper bound
    // on the overlap is left, a cap like the sub-steps' above rather than an error.
    def.solver.classicAllowedPenetration =
        std::min(metres(config.allowedPenetration), physics::kMaxClassicAllowedPenetration);
    def.solver.classicPositionBias = config.penetrationBiasFactor;
    return def;
}

EngineConfigResult loadEngineConfig(const std::filesystem::path& path, bool required) {
    EngineConfigResult result;
    std::error_code ec;
    const bool exists = std::filesystem::is_regular_file(path, ec);
    if (!exists) {
        const std::string message = path.string() + ": cannot read the configuration file";
        if (required) {
            result.errors.push_back(message);
        } else {
            result.warnings.push_back(message + ", using the defaults");
        }
        result.config.assetRoot = std::filesystem::current_path(ec);
        return result;
    }
    const core::ConfigResult loaded = core::loadConfig(path);
    static_cast<core::Config&>(result.config) = loaded.config;
    result.config.file = path;
    std::filesystem::path root = path.parent_path();
    if (root.empty()) {
        root = std::filesystem::current_path(ec);
    }
    result.config.assetRoot = root;
    for (const core::ConfigDiagnostic& d : loaded.diagnostics) {
        (d.severity == core::ConfigDiagnostic::Severity::Error ? result.errors : result.warnings)
            .push_back(d.toString());
    }
    return result;
}

} // namespace e2d::engine
