// SPDX-License-Identifier: MIT
// Shared helpers for the core tests: an event recorder and a minimal SceneHost.
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene_host.hpp>

#include <string>
#include <utility>
#include <vector>

namespace e2d::core::test {

/// Appends "tag:event" strings, so tests can compare whole event sequences.
struct EventLog {
    std::vector<std::string> events;
    void add(const std::string& tag, const char* event) { events.push_back(tag + ":" + event); }
    void clear() { events.clear(); }
};

/// A test event: any struct can be one (see handles.hpp).
struct Ping {
    int value = 0;
};
/// Another, that Recorder does not handle.
struct Pong {
    int value = 0;
};

/// Records its lifecycle, update and Ping events into an EventLog.
class Recorder : public Component, public Handles<Ping> {
public:
    Recorder(EventLog& log, std::string tag) : log_(log), tag_(std::move(tag)) {}
    ~Recorder() override { log_.add(tag_, "destroyed"); }
    void onAddedToGameObject() override { log_.add(tag_, "added"); }
    void onRemovedFromGameObject() override { log_.add(tag_, "removed"); }
    void onInitialize() override { log_.add(tag_, "init"); }
    void onTerminate() override { log_.add(tag_, "term"); }
    void update(double) override { log_.add(tag_, "update"); }
    void fixedUpdate(double) override { log_.add(tag_, "fixed"); }
    void on(const Ping&) override { log_.add(tag_, "ping"); }

private:
    EventLog& log_;
    std::string tag_;
};

/// A SceneHost that records requests and logs into memory.
class TestHost : public SceneHost {
public:
    TestHost()
        : logger_(LogLevel::Trace, [this](LogLevel level, std::string_view message) {
              messages.emplace_back(level, std::string(message));
          }) {}
    void changeToScene(std::string_view name) override { requestedScene = std::string(name); }
    void terminateGame() override { terminateRequested = true; }
    glm::ivec2 windowSize() const override { return {800, 600}; }
    glm::ivec2 referenceWindowSize() const override { return {1024, 624}; }
    Logger& logger() override { return logger_; }

    std::vector<std::pair<LogLevel, std::string>> messages;
    std::string requestedScene;
    bool terminateRequested = false;

private:
    Logger logger_;
};

} // namespace e2d::core::test
