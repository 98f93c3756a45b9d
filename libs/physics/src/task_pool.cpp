// SPDX-License-Identifier: MIT
#include "task_pool.hpp"

#include <algorithm>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace e2d::physics::detail {

namespace {

inline void pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

// Spins before an idle thread sleeps: about the gap between two stages of a step.
constexpr int kSpinsBeforeSleep = 4000;

// The claim word: generation (24 bits), piece count and next piece (20 bits each).
constexpr int kPieceBits = 20;
constexpr std::uint32_t kMaxPieces = (1u << kPieceBits) - 1;
constexpr std::uint32_t kGenerationMask = (1u << 24) - 1;

constexpr std::uint64_t pack(std::uint32_t generation, std::uint32_t count, std::uint32_t next) {
    return (static_cast<std::uint64_t>(generation) << (2 * kPieceBits)) |
           (static_cast<std::uint64_t>(count) << kPieceBits) | next;
}
constexpr std::uint32_t generationOf(std::uint64_t claim) {
    return static_cast<std::uint32_t>(claim >> (2 * kPieceBits));
}
constexpr std::uint32_t countOf(std::uint64_t claim) {
    return static_cast<std::uint32_t>(claim >> kPieceBits) & kMaxPieces;
}
constexpr std::uint32_t nextOf(std::uint64_t claim) {
    return static_cast<std::uint32_t>(claim) & kMaxPieces;
}

} // namespace

// Whether `workers` threads fit on this machine's hardware threads.
bool fitsHardware(int workers) {
    const unsigned hardware = std::thread::hardware_concurrency();
    return hardware == 0 || static_cast<unsigned>(workers) <= hardware;
}

TaskPool::TaskPool(int workerCount) : spins_(fitsHardware(workerCount) ? kSpinsBeforeSleep : 0) {
    threads_.reserve(static_cast<std::size_t>(std::max(workerCount - 1, 0)));
    for (int worker = 1; worker < workerCount; ++worker) {
        threads_.emplace_back([this, worker] { threadMain(worker); });
    }
}

TaskPool::~TaskPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) {
        t.join();
    }
}

void TaskPool::run(TaskFunction task, int itemCount, int pieceSize, void* context) {
    // At most kMaxPieces pieces.
    pieceSize = std::max(
        {pieceSize, 1, static_cast<int>(static_cast<std::uint32_t>(itemCount) / kMaxPieces) + 1});
    const auto pieceCount = static_cast<std::uint32_t>((itemCount + pieceSize - 1) / pieceSize);
    task_ = task;
    context_ = context;
    itemCount_ = itemCount;
    pieceSize_ = pieceSize;
    done_.store(0, std::memory_order_relaxed);
    generation_ = (generation_ + 1) & kGenerationMask;
    const std::uint32_t generation = generation_;
    bool notify = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        claim_.store(pack(generation, pieceCount, 0), std::memory_order_release);
        notify = sleeping_ > 0;
    }
    if (notify) {
        wake_.notify_all();
    }
    runPieces(generation, 0);
    for (int spins = 0; done_.load(std::memory_order_acquire) != static_cast<int>(pieceCount);
         ++spins) {
        if (spins < spins_) {
            pause();
        } else {
            std::this_thread::yield(); // a worker holding a piece was preempted
        }
    }
}

void TaskPool::runPieces(std::uint32_t generation, int worker) {
    std::uint64_t claim = claim_.load(std::memory_order_acquire);
    for (;;) {
        if (generationOf(claim) != generation || nextOf(claim) >= countOf(claim)) {
            return; // every piece is taken, or a newer task is out
        }
        if (!claim_.compare_exchange_weak(claim, claim + 1, std::memory_order_acq_rel,
                                          std::memory_order_acquire)) {
            continue;
        }
        const int begin = static_cast<int>(nextOf(claim)) * pieceSize_;
        task_(begin, std::min(begin + pieceSize_, itemCount_), worker, context_);
        done_.fetch_add(1, std::memory_order_release);
        claim = claim_.load(std::memory_order_acquire);
    }
}

void TaskPool::threadMain(int worker) {
    std::uint32_t seen = 0;
    auto published = [this] { return generationOf(claim_.load(std::memory_order_acquire)); };
    for (;;) {
        std::uint32_t generation = published();
        for (int spins = 0; generation == seen && spins < spins_; ++spins) {
            pause();
            generation = published();
        }
        if (generation == seen) {
            std::unique_lock<std::mutex> lock(mutex_);
            ++sleeping_;
            wake_.wait(lock, [&] { return stop_ || published() != seen; });
            --sleeping_;
            if (stop_) {
                return;
            }
            generation = published();
        }
        seen = generation;
        runPieces(generation, worker);
    }
}

void StageRunner::reset(std::span<const int> blockCounts, int workerCount) {
    workers_ = std::max(workerCount, 1);
    const std::size_t stages = blockCounts.size();
    const std::size_t ranges = stages * static_cast<std::size_t>(workers_);
    if (stages > stageCapacity_) {
        stageCapacity_ = stages;
        stages_ = std::make_unique<Stage[]>(stages);
    }
    if (ranges > rangeCapacity_) {
        rangeCapacity_ = ranges;
        ranges_ = std::make_unique<Range[]>(ranges);
    }
    count_ = static_cast<int>(stages);
    for (std::size_t k = 0; k < stages; ++k) {
        const int blocks = std::max(blockCounts[k], 1);
        stages_[k].done.store(0, std::memory_order_relaxed);
        stages_[k].blocks = blocks;
        for (int w = 0; w < workers_; ++w) {
            Range& range =
                ranges_[k * static_cast<std::size_t>(workers_) + static_cast<std::size_t>(w)];
            range.next.store(blocks * w / workers_, std::memory_order_relaxed);
            range.end = blocks * (w + 1) / workers_;
        }
    }
    cursor_->stage.store(0, std::memory_order_relaxed);
    spins_ = fitsHardware(workers_) ? kSpinsBeforeSleep : 0;
}

void StageRunner::join(int worker, Function function, void* context) {
    std::atomic<int>& cursor = cursor_->stage;
    int k = cursor.load(std::memory_order_acquire);
    while (k < count_) {
        Stage& stage = stages_[static_cast<std::size_t>(k)];
        Range* ranges = &ranges_[static_cast<std::size_t>(k) * static_cast<std::size_t>(workers_)];
        int ran = 0;
        // Its own range first, then the others' in turn.
        for (int i = 0; i < workers_; ++i) {
            Range& range = ranges[(worker + i) % workers_];
            for (int block = range.next.fetch_add(1, std::memory_order_relaxed); block < range.end;
                 block = range.next.fetch_add(1, std::memory_order_relaxed)) {
                function(k, block, worker, context);
                ++ran;
            }
        }
        // The worker that completes a stage opens the next; its acquire-release chain on
        // `done` carries every block's writes to whoever reads the cursor after.
        if (ran > 0 && stage.done.fetch_add(ran, std::memory_order_acq_rel) + ran == stage.blocks) {
            cursor.store(++k, std::memory_order_release);
            continue;
        }
        int next = cursor.load(std::memory_order_acquire);
        for (int spins = 0; next == k; ++spins) {
            if (spins < spins_) {
                pause();
            } else {
                std::this_thread::yield(); // the worker holding a block was preempted
            }
            next = cursor.load(std::memory_order_acquire);
        }
        k = next;
    }
}

void Tasks::configure(int workerCount, int minSplitWork, EnqueueTaskFunction enqueue,
                      FinishTaskFunction finish, void* userContext) {
    workerCount_ = workerCount;
    minSplitWork_ = minSplitWork;
    enqueue_ = enqueue;
    finish_ = finish;
    userContext_ = userContext;
    pool_.reset();
    if (workerCount > 1 && enqueue == nullptr) {
        pool_ = std::make_unique<TaskPool>(workerCount);
    }
}

void Tasks::run(TaskFunction task, int itemCount, int minRange, void* context) {
    // Pieces small enough that a worker slowed by the rest of the machine, or woken late,
    // leaves little for the others to wait on: a stage that splits at all is at least two
    // minRange's worth (parallelFor()), so a piece is still several microseconds.
    const int pieceSize = std::max({1, itemCount / (8 * workerCount_), minRange / 8});
    if (enqueue_ != nullptr) {
        void* userTask = enqueue_(task, itemCount, pieceSize, context, userContext_);
        if (userTask != nullptr) {
            finish_(userTask, userContext_);
        }
        return;
    }
    pool_->run(task, itemCount, pieceSize, context);
}

} // namespace e2d::physics::detail
