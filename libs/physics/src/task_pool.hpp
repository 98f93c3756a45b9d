// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/task.hpp>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <type_traits>
#include <vector>

// The step's parallel-for (detail::Tasks) and the world's own threads behind it (TaskPool)
// when the game gives no job system (WorldDef::enqueueTask).
namespace e2d::physics::detail {

// workerCount - 1 threads and the caller run one task at a time: the caller publishes it, every
// worker (the caller as worker 0) claims pieces through one atomic counter until none is left,
// and the caller returns once every piece has run. Idle threads spin a little (the step's
// stages follow one another within microseconds), then sleep on a condition variable.
class TaskPool {
public:
    explicit TaskPool(int workerCount);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    // Runs task over [0, itemCount) in pieces of pieceSize items; returns when all are done.
    void run(TaskFunction task, int itemCount, int pieceSize, void* context);

private:
    void threadMain(int worker);
    // Claims and runs pieces of task `generation` until none is left.
    void runPieces(std::uint32_t generation, int worker);

    std::vector<std::thread> threads_;
    // Spins before a wait yields or sleeps: none when there are more workers than hardware
    // threads (a spinning worker then only takes time from the one it waits for).
    int spins_ = 0;
    std::mutex mutex_;
    std::condition_variable wake_;
    int sleeping_ = 0;  // threads waiting on wake_ (mutex_)
    bool stop_ = false; // (mutex_)
    // The task's generation, piece count and next unclaimed piece in one word (see pack()): a
    // piece is claimed by one compare-and-swap that also checks which task it belongs to, so a
    // thread that wakes late never runs a piece twice or reads a newer task's fields for an
    // older one. The fields below are written before a task is published and read only by a
    // thread holding one of its pieces.
    std::atomic<std::uint64_t> claim_{0};
    std::atomic<int> done_{0}; // pieces of the current task that have run
    std::uint32_t generation_ = 0;
    TaskFunction task_ = nullptr;
    void* context_ = nullptr;
    int itemCount_ = 0;
    int pieceSize_ = 1;
};

// Whether `workers` threads fit on this machine's hardware threads (or it does not say).
bool fitsHardware(int workers);

// A sequence of stages that every worker joining runs together (the soft step of one large
// block of islands, soft_step_stages.cpp): stage k's blocks [0, blocks(k)) are claimed one at a
// time through atomic counters by whoever is there, and no worker starts stage k + 1 before
// every block of stage k has run. A worker only ever waits for blocks another one has claimed
// and is running, never for a worker to arrive: the stages complete with any number of workers
// joining at any time, on any job system (one that runs the pieces one after another too: the
// first does everything, the others find nothing left). Each stage's blocks are cut into one
// range per worker, which that worker claims from first (in order) before it helps with the
// others' (Box2D v3's solver stages do the same): a worker then mostly takes the same part of
// each pass, and its bodies stay in its cache from pass to pass.
class StageRunner {
public:
    // Runs block `block` of stage `stage` on worker `worker`.
    using Function = void (*)(int stage, int block, int worker, void* context);

    StageRunner() = default;
    StageRunner(const StageRunner&) = delete;
    StageRunner& operator=(const StageRunner&) = delete;
    StageRunner(StageRunner&&) noexcept = default;
    StageRunner& operator=(StageRunner&&) noexcept = default;

    // Sets the stages for the next run, blockCounts[k] (at least 1) blocks for stage k, for up
    // to workerCount workers (which also decides how long a waiting worker spins before it
    // yields). Not while a run is going on.
    void reset(std::span<const int> blockCounts, int workerCount);
    // Runs blocks of the current stage and the ones after it until every stage is done.
    // worker: in [0, workerCount).
    void join(int worker, Function function, void* context);

private:
    // A worker's range of a stage's blocks: the next unclaimed one and the end.
    struct alignas(64) Range {
        std::atomic<int> next{0};
        int end = 0;
    };
    struct alignas(64) Stage {
        std::atomic<int> done{0}; // blocks that have run
        int blocks = 0;
    };
    std::unique_ptr<Stage[]> stages_;
    std::unique_ptr<Range[]> ranges_; // stage k's: [k * workers_, (k + 1) * workers_)
    std::size_t stageCapacity_ = 0;
    std::size_t rangeCapacity_ = 0;
    int count_ = 0;
    int workers_ = 1;
    int spins_ = 0;
    // The first stage not done yet (count_ when all are).
    struct alignas(64) Cursor {
        std::atomic<int> stage{0};
    };
    std::unique_ptr<Cursor> cursor_ = std::make_unique<Cursor>();
};

// How World::step() runs its parallel stages (WorldDef::workerCount, enqueueTask, finishTask).
class Tasks {
public:
    Tasks() = default;
    Tasks(const Tasks&) = delete;
    Tasks& operator=(const Tasks&) = delete;
    // Movable: World::restoreSnapshot() hands the world's workers to its restored state.
    Tasks(Tasks&&) noexcept = default;
    Tasks& operator=(Tasks&&) noexcept = default;

    // Starts the world's own threads when workerCount > 1 and enqueue is null. minSplitWork:
    // WorldDef::minSplitWork.
    void configure(int workerCount, int minSplitWork, EnqueueTaskFunction enqueue,
                   FinishTaskFunction finish, void* userContext);
    [[nodiscard]] int workerCount() const { return workerCount_; }

    // The minRange of parallelFor() for items of about `nanosecondsEach` (one worker,
    // measured in bench/solver): half of WorldDef::minSplitWork, so a stage splits once it
    // holds the whole of it. Depends on the scene's counts only, never on a timing.
    [[nodiscard]] int minRange(int nanosecondsEach) const {
        return std::max(1, minSplitWork_ / (2 * std::max(nanosecondsEach, 1)));
    }

    // Calls body(begin, end, worker) over [0, itemCount) in pieces of at least minRange items
    // (worker in [0, workerCount())); returns when every piece has run. One worker, or fewer
    // than two pieces' worth of items (minPieceItems()): one piece, here.
    template <class Body>
    void parallelFor(int itemCount, int minRange, Body&& body) {
        if (itemCount <= 0) {
            return;
        }
        if (workerCount_ == 1 || itemCount / 2 < std::max(minRange, 1)) {
            body(0, itemCount, 0);
            return;
        }
        auto trampoline = [](int begin, int end, int worker, void* context) {
            (*static_cast<std::remove_reference_t<Body>*>(context))(begin, end, worker);
        };
        run(trampoline, itemCount, minRange, &body);
    }

private:
    void run(TaskFunction task, int itemCount, int minRange, void* context);

    int workerCount_ = 1;
    int minSplitWork_ = 0;
    EnqueueTaskFunction enqueue_ = nullptr;
    FinishTaskFunction finish_ = nullptr;
    void* userContext_ = nullptr;
    std::unique_ptr<TaskPool> pool_;
};

} // namespace e2d::physics::detail
