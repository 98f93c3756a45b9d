// SPDX-License-Identifier: MIT
#pragma once

/// The step's task interface: how World::step() hands its parallel work (narrow phase, the
/// solver's blocks of islands) to a job system. By default a world with
/// WorldDef::workerCount > 1 runs it on a small pool of threads it owns; a game with its own job
/// system sets WorldDef::enqueueTask and WorldDef::finishTask instead, so the physics shares its
/// threads. Either way the results do not depend on the worker count or on which worker ran
/// what: every parallel stage writes per-item results, and what is gathered from them is put in
/// a fixed order.
namespace e2d::physics {

/// A piece of a parallel task: items [begin, end), run by worker `worker`. The job system calls
/// it with `taskContext` as given to EnqueueTaskFunction. `worker` names the thread the piece
/// runs on: in [0, WorldDef::workerCount), and never the same for two pieces running at once
/// (the step keeps scratch memory per worker).
using TaskFunction = void (*)(int begin, int end, int worker, void* taskContext);

/// Starts `task` over the items [0, itemCount), split into pieces of at least `minRange` items
/// (fewer only when itemCount is smaller), each item in exactly one piece, on any workers.
/// `userContext` is WorldDef::userTaskContext. Returns a handle that FinishTaskFunction waits
/// for, or nullptr when every piece already ran inside this call (then finish is not called).
/// Called from the thread that called World::step(), one task at a time.
using EnqueueTaskFunction = void* (*)(TaskFunction task, int itemCount, int minRange,
                                      void* taskContext, void* userContext);

/// Returns once every piece of `userTask` (EnqueueTaskFunction's handle) has run.
using FinishTaskFunction = void (*)(void* userTask, void* userContext);

/// The most workers a world splits its step over (WorldDef::workerCount).
inline constexpr int kMaxWorkers = 64;

} // namespace e2d::physics
