// SPDX-License-Identifier: MIT
// Threads change the speed of World::step() only: the same scene stepped with 1, 2, 3 and 8
// workers, on the SSE2 (4 lanes) and AVX2 (8 lanes) solver paths, and on a job system of the
// test's own (WorldDef::enqueueTask), ends bit for bit the same, events included.
#include "joint_test_util.hpp"
#include "world_step_util.hpp"
#include "world_test_util.hpp"

#include <e2d/physics/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace e2d::physics::test {
namespace {

// FNV-1a over raw bits.
struct Hash {
    std::uint64_t h = 1469598103934665603ull;
    void add(std::uint32_t bits) { h = (h ^ bits) * 1099511628211ull; }
    void add(float x) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        add(bits);
    }
    void add(Vec2 v) {
        add(v.x);
        add(v.y);
    }
    void add(ShapeId id) { add(id.index1); }
    void add(BodyId id) { add(id.index1); }
};

// One scene: a world and the bodies whose state is hashed.
struct Scene {
    World world;
    std::vector<BodyId> bodies;
};

WorldDef threadedDef(int workers, int lanes, SolverMode mode = SolverMode::SoftStep) {
    WorldDef def;
    def.tag = 7; // the same ids in every world, so events hash alike
    def.workerCount = workers;
    def.minSplitWork = 0; // every stage split: what the hashes compare
    def.simdLanes = lanes;
    def.solver.mode = mode;
    return def;
}

// Many small piles side by side (several of the wide solver's blocks, some asleep later),
// bouncy balls dropped on them (restitution, hit events), a hanging chain of hinges with a
// box at its end swinging through the piles, a ragdoll-like pair with a limited hinge and a
// weld, and a bullet fired at the far pile (continuous collision).
void buildMixed(Scene& s) {
    World& w = s.world;
    addGround(w);
    Random random(5);
    for (int pile = 0; pile < 6; ++pile) {
        const float x0 = -15.0f + 6.0f * static_cast<float>(pile);
        for (int row = 0; row < 5; ++row) {
            for (int col = 0; col < 5 - row; ++col) {
                const Vec2 p{x0 + 1.05f * static_cast<float>(col) +
                                 0.525f * static_cast<float>(row),
                             0.5f + 1.0f * static_cast<float>(row)};
                s.bodies.push_back(addBox(w, p, 0.5f));
            }
        }
        s.bodies.push_back(addBall(w, {x0 + 2.0f, 8.0f + random.uniform(0.0f, 2.0f)},
                                   random.uniform(0.2f, 0.4f), 0.6f));
    }
    const BodyId anchor = addStatic(w, {0.0f, 14.0f});
    BodyId previous = anchor;
    for (int i = 0; i < 10; ++i) {
        const BodyId link = addPlank(w, {0.5f + static_cast<float>(i), 14.0f}, 0.5f, 0.1f);
        RevoluteJointDef jd;
        jd.bodyA = previous;
        jd.bodyB = link;
        jd.localAnchorA = previous == anchor ? Vec2{0.0f, 0.0f} : Vec2{0.5f, 0.0f};
        jd.localAnchorB = {-0.5f, 0.0f};
        w.createJoint(jd);
        s.bodies.push_back(link);
        previous = link;
    }
    const BodyId weight = addBox(w, {11.0f, 14.0f}, 0.6f);
    RevoluteJointDef end;
    end.bodyA = previous;
    end.bodyB = weight;
    end.localAnchorA = {0.5f, 0.0f};
    end.localAnchorB = {-0.6f, 0.0f};
    end.enableLimit = true;
    end.lowerAngle = -0.5f;
    end.upperAngle = 0.5f;
    w.createJoint(end);
    s.bodies.push_back(weight);
    const BodyId torso = addPlank(w, {-20.0f, 6.0f}, 0.3f, 0.6f);
    const BodyId head = addDisc(w, {-20.0f, 7.0f}, 0.3f);
    WeldJointDef neck;
    neck.bodyA = torso;
    neck.bodyB = head;
    neck.localAnchorA = {0.0f, 0.6f};
    neck.localAnchorB = {0.0f, -0.4f};
    w.createJoint(neck);
    s.bodies.push_back(torso);
    s.bodies.push_back(head);
    BodyDef bullet;
    bullet.type = BodyType::Dynamic;
    bullet.isBullet = true;
    bullet.position = {-40.0f, 1.0f};
    bullet.linearVelocity = {200.0f, 0.0f};
    const BodyId shot = w.createBody(bullet);
    w.createShape(shot, {}, Circle{{0.0f, 0.0f}, 0.1f});
    s.bodies.push_back(shot);
}

// A random pile of boxes and balls spawned overlapping (the soft step's push-out sweeps).
void buildPile(Scene& s) {
    addGround(s.world);
    Random random(11);
    for (int i = 0; i < 40; ++i) {
        const Vec2 p{random.uniform(-2.0f, 2.0f), 0.5f + 0.45f * static_cast<float>(i)};
        if (i % 2 == 0) {
            s.bodies.push_back(addBox(s.world, p, random.uniform(0.2f, 0.5f), 0.6f, 1.0f,
                                      random.uniform(-1.0f, 1.0f)));
        } else {
            s.bodies.push_back(addBall(s.world, p, random.uniform(0.2f, 0.5f), 0.3f));
        }
    }
}

// A static ground 1 m thick whose top is y = 0, from x = -halfWidth to halfWidth.
void addLongGround(World& world, float halfWidth) {
    BodyDef ground;
    ground.position = {0.0f, -0.5f};
    const BodyId floor = world.createBody(ground);
    world.createShape(floor, {}, makeBox(halfWidth, 0.5f));
}

// Short stacks of three boxes dropped from a little above each other onto one long ground:
// more constraints than one block of the wide solver holds (World::Impl::scheduleWide()), so
// the blocks are solved on several workers, and all stacks land in the same steps (hit events
// from every block at once).
void buildStacks(Scene& s) {
    constexpr int kStacks = 1500;
    addLongGround(s.world, 0.8f * kStacks + 2.0f);
    for (int i = 0; i < kStacks; ++i) {
        const float x = 1.6f * (static_cast<float>(i) - 0.5f * kStacks);
        for (int level = 0; level < 3; ++level) {
            s.bodies.push_back(addBox(s.world, {x, 0.7f + 1.2f * static_cast<float>(level)}, 0.5f));
        }
    }
}

// buildStacks()'s stacks, each with a plank hinged to the side of its top box, swinging down to
// its hinge's limit: joints in every block of the wide solver, so the blocks of a world with
// joints are solved on several workers too (each worker with its own arrays for the direct
// joint solve, the default).
void buildJointedStacks(Scene& s) {
    buildStacks(s);
    std::vector<BodyId> tops;
    for (std::size_t i = 2; i < s.bodies.size(); i += 3) {
        tops.push_back(s.bodies[i]);
    }
    for (BodyId top : tops) {
        const Vec2 p = s.world.transform(top).p;
        // Shorter than the gap to the next stack: each stack stays its own island.
        const BodyId plank = addPlank(s.world, {p.x + 0.75f, p.y}, 0.25f, 0.08f);
        RevoluteJointDef jd;
        jd.bodyA = top;
        jd.bodyB = plank;
        jd.localAnchorA = {0.5f, 0.0f};
        jd.localAnchorB = {-0.25f, 0.0f};
        jd.enableLimit = true;
        jd.lowerAngle = -0.8f;
        jd.upperAngle = 0.3f;
        s.world.createJoint(jd);
        s.bodies.push_back(plank);
    }
}

// A row of small boxes settling on the ground (they fall asleep after half a second) and balls
// flying out of the coordinate range (kHuge), a few each step: the write-back on several
// workers, with bodies disabled in the same steps others fall asleep (the move events).
void buildRunaways(Scene& s) {
    addGround(s.world);
    for (int i = 0; i < 400; ++i) {
        s.bodies.push_back(addBox(s.world, {-90.0f + 0.45f * static_cast<float>(i), 0.25f}, 0.2f));
    }
    constexpr float kSpeed = 400.0f;
    for (int j = 0; j < 200; ++j) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {kHuge - (static_cast<float>(j / 5) + 0.5f) * kSpeed * kStep,
                       3.0f + 0.5f * static_cast<float>(j)};
        bd.linearVelocity = {kSpeed, 0.0f};
        const BodyId ball = s.world.createBody(bd);
        s.world.createShape(ball, {}, Circle{{0.0f, 0.0f}, 0.1f});
        s.bodies.push_back(ball);
    }
}

// A row of boxes resting apart on one long ground, two of every three of which fall asleep
// after half a second while the third stays awake: past then, the touching contacts of the
// sleeping ones are left out of the solve in every chunk of the solver's walk over them
// (World::Impl::solve()), which closes the chunks up in order.
void buildHalfAsleepRow(Scene& s) {
    constexpr int kBoxes = 1600;
    addLongGround(s.world, 0.5f * kBoxes + 2.0f);
    for (int i = 0; i < kBoxes; ++i) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {static_cast<float>(i) - 0.5f * kBoxes, 0.2f};
        bd.enableSleep = i % 3 != 0;
        const BodyId box = s.world.createBody(bd);
        s.world.createShape(box, {}, makeBox(0.2f, 0.2f));
        s.bodies.push_back(box);
    }
}

// A pyramid of unit boxes on the ground, `base` boxes wide.
void addPyramid(Scene& s, int base) {
    addGround(s.world);
    for (int row = 0; row < base; ++row) {
        for (int col = 0; col < base - row; ++col) {
            const Vec2 p{1.0f * static_cast<float>(col) + 0.5f * static_cast<float>(row) -
                             0.5f * static_cast<float>(base),
                         0.5f + 1.0f * static_cast<float>(row)};
            s.bodies.push_back(addBox(s.world, p, 0.5f));
        }
    }
}

// One pyramid of base 40: one island, and one block of the wide solver that all workers solve
// together, colour by colour (StepCounters::stagedConstraints).
void buildPyramid(Scene& s) { addPyramid(s, 40); }

// A pyramid of base 30 (one island, solved by all workers together) struck by bouncy balls
// (restitution and hit events inside it), with a box spawned into its top (the push-out
// sweeps).
void buildStruckPyramid(Scene& s) {
    constexpr int kBase = 30;
    addPyramid(s, kBase);
    for (float x : {-9.0f, -4.0f, 3.0f, 8.0f}) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {x, static_cast<float>(kBase) - 2.0f * std::fabs(x) + 1.5f};
        bd.linearVelocity = {0.0f, -8.0f};
        const BodyId ball = s.world.createBody(bd);
        ShapeDef sd;
        sd.restitution = 0.8f;
        s.world.createShape(ball, sd, Circle{{0.0f, 0.0f}, 0.4f});
        s.bodies.push_back(ball);
    }
    s.bodies.push_back(addBox(s.world, {0.1f, static_cast<float>(kBase) - 0.1f}, 0.5f));
}

// Steps the scene; hashes every step's transforms, velocities and events.
std::uint64_t run(const WorldDef& def, void (*build)(Scene&), int steps) {
    Scene s{World{def}, {}};
    build(s);
    Hash hash;
    for (int i = 0; i < steps; ++i) {
        s.world.step(kStep);
        for (BodyId id : s.bodies) {
            const Transform xf = s.world.transform(id);
            hash.add(xf.p);
            hash.add(xf.q.c);
            hash.add(xf.q.s);
            hash.add(s.world.linearVelocity(id));
            hash.add(s.world.angularVelocity(id));
        }
        for (const ContactBeginTouchEvent& e : s.world.contactBeginEvents()) {
            hash.add(e.shapeA);
            hash.add(e.shapeB);
        }
        for (const ContactEndTouchEvent& e : s.world.contactEndEvents()) {
            hash.add(e.shapeA);
            hash.add(e.shapeB);
        }
        for (const ContactHitEvent& e : s.world.hitEvents()) {
            hash.add(e.shapeA);
            hash.add(e.shapeB);
            hash.add(e.point);
            hash.add(e.approachSpeed);
        }
        for (const BodyMoveEvent& e : s.world.bodyMoveEvents()) {
            hash.add(e.body);
            hash.add(e.transform.p);
            hash.add(e.transform.q.s);
            hash.add(e.fellAsleep ? 1u : 0u);
        }
        for (BodyId id : s.world.outOfRangeBodies()) {
            hash.add(id);
        }
    }
    return hash.h;
}

struct Case {
    const char* name;
    void (*build)(Scene&);
    SolverMode mode;
    int steps;
};

const Case kCases[] = {
    {"mixed", buildMixed, SolverMode::SoftStep, 100},
    {"mixed_classic", buildMixed, SolverMode::Classic, 60},
    {"pile", buildPile, SolverMode::SoftStep, 120},
    {"stacks", buildStacks, SolverMode::SoftStep, 20},
    {"jointed_stacks", buildJointedStacks, SolverMode::SoftStep, 20},
    {"pyramid", buildPyramid, SolverMode::SoftStep, 12},
    {"struck_pyramid", buildStruckPyramid, SolverMode::SoftStep, 20},
    {"runaways", buildRunaways, SolverMode::SoftStep, 40},
    {"half_asleep_row", buildHalfAsleepRow, SolverMode::SoftStep, 40},
};

TEST(WorldThreads, EveryWorkerCountAndSimdWidthGivesTheSameSteps) {
    for (const Case& c : kCases) {
        const std::uint64_t reference = run(threadedDef(1, 8, c.mode), c.build, c.steps);
        for (int lanes : {4, 8}) {
            for (int workers : {1, 2, 3, 8}) {
                EXPECT_EQ(run(threadedDef(workers, lanes, c.mode), c.build, c.steps), reference)
                    << c.name << ", " << workers << " workers, " << lanes << " lanes";
            }
        }
    }
}

// half_asleep_row is what it says: by its last step the solver runs the awake third of the
// boxes' contacts only, more than one chunk of the walk over the touching contacts apart.
TEST(WorldThreads, HalfAsleepRowLeavesOutTheSleepingContacts) {
    Scene s{World{threadedDef(2, 8)}, {}};
    buildHalfAsleepRow(s);
    for (int i = 0; i < 40; ++i) {
        s.world.step(kStep);
    }
    const auto awake = std::count_if(s.bodies.begin(), s.bodies.end(),
                                     [&](BodyId id) { return s.world.isAwake(id); });
    EXPECT_EQ(awake, (s.bodies.size() + 2) / 3);
    EXPECT_EQ(s.world.stepCounters().contactConstraints, awake);
}

// Recycling decides per contact from that contact's bodies alone: the same on every worker.
TEST(WorldThreads, RecycledContactsGiveTheSameStepsOnEveryWorkerCount) {
    for (const Case& c : kCases) {
        WorldDef def = threadedDef(1, 8, c.mode);
        def.solver.contactRecycleDistance = 0.02f;
        const std::uint64_t reference = run(def, c.build, c.steps);
        for (int workers : {2, 3, 8}) {
            def.workerCount = workers;
            EXPECT_EQ(run(def, c.build, c.steps), reference) << c.name << ", " << workers;
        }
    }
}

// A job system of the test's own: `threads` threads taking pieces from a queue, each piece
// run with its thread's index as the worker; finish waits for the task's pieces.
class JobSystem {
public:
    explicit JobSystem(int threads) {
        for (int i = 0; i < threads; ++i) {
            threads_.emplace_back([this, i] { work(i); });
        }
    }
    ~JobSystem() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        ready_.notify_all();
        for (std::thread& t : threads_) {
            t.join();
        }
    }

    static void* enqueue(TaskFunction task, int itemCount, int minRange, void* taskContext,
                         void* userContext) {
        auto& jobs = *static_cast<JobSystem*>(userContext);
        ++jobs.tasks;
        const int piece = std::max(minRange, 1);
        std::lock_guard<std::mutex> lock(jobs.mutex_);
        for (int begin = 0; begin < itemCount; begin += piece) {
            const int end = std::min(begin + piece, itemCount);
            ++jobs.pending_;
            jobs.queue_.push_back([=](int worker) { task(begin, end, worker, taskContext); });
        }
        jobs.ready_.notify_all();
        return &jobs;
    }
    static void finish(void* userTask, void* userContext) {
        EXPECT_EQ(userTask, userContext);
        auto& jobs = *static_cast<JobSystem*>(userContext);
        std::unique_lock<std::mutex> lock(jobs.mutex_);
        jobs.done_.wait(lock, [&] { return jobs.pending_ == 0; });
    }

    int tasks = 0; // enqueued so far

private:
    void work(int worker) {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            ready_.wait(lock, [&] { return stop_ || !queue_.empty(); });
            if (stop_) {
                return;
            }
            std::function<void(int)> job = std::move(queue_.front());
            queue_.pop_front();
            lock.unlock();
            job(worker);
            lock.lock();
            if (--pending_ == 0) {
                done_.notify_all();
            }
        }
    }

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable ready_;
    std::condition_variable done_;
    std::deque<std::function<void(int)>> queue_;
    int pending_ = 0;
    bool stop_ = false;
};

TEST(WorldThreads, TheGamesJobSystemRunsTheStepWithTheSameResults) {
    const std::uint64_t reference = run(threadedDef(1, 8), buildMixed, 150);
    JobSystem jobs(3);
    WorldDef def = threadedDef(3, 8);
    def.enqueueTask = JobSystem::enqueue;
    def.finishTask = JobSystem::finish;
    def.userTaskContext = &jobs;
    EXPECT_EQ(run(def, buildMixed, 150), reference);
    // The step's work went through it: the narrow phase of every step at least.
    EXPECT_GE(jobs.tasks, 150);
    // A pile its three threads solve together, stage by stage.
    EXPECT_EQ(run(def, buildStruckPyramid, 20), run(threadedDef(1, 8), buildStruckPyramid, 20));
}

// A small scene's stages are far below WorldDef::minSplitWork: the caller runs them alone
// (handing them to a second thread made its steps slower) with the same results.
TEST(WorldThreads, ASmallScenesStagesRunOnTheCaller) {
    const std::uint64_t reference = run(threadedDef(1, 8), buildMixed, 150);
    JobSystem jobs(3);
    WorldDef def = threadedDef(3, 8);
    def.minSplitWork = WorldDef{}.minSplitWork;
    def.enqueueTask = JobSystem::enqueue;
    def.finishTask = JobSystem::finish;
    def.userTaskContext = &jobs;
    EXPECT_EQ(run(def, buildMixed, 150), reference);
    EXPECT_EQ(jobs.tasks, 0);
}

// A pile holding more than a worker's share of the constraints is solved by all workers
// together (so the cases above split one island across workers); small piles each go whole to
// one worker, and one worker solves everything whole.
TEST(WorldThreads, ALargeIslandIsSolvedByAllWorkersTogether) {
    for (int workers : {1, 2, 3}) {
        Scene pyramid{World{threadedDef(workers, 8)}, {}};
        buildStruckPyramid(pyramid);
        Scene piles{World{threadedDef(workers, 8)}, {}};
        buildMixed(piles);
        int hits = 0;
        for (int i = 0; i < 20; ++i) {
            pyramid.world.step(kStep);
            piles.world.step(kStep);
            const StepCounters counters = pyramid.world.stepCounters();
            EXPECT_GT(counters.contactConstraints, 1000);
            EXPECT_EQ(counters.stagedConstraints, workers > 1 ? counters.contactConstraints : 0)
                << workers << " workers, step " << i;
            EXPECT_EQ(piles.world.stepCounters().stagedConstraints, 0) << workers << " workers";
            // The box spawned into the top is pushed out in the first step (more sweeps).
            if (i == 0) {
                EXPECT_GT(counters.relaxIterations, 1);
            }
            hits += static_cast<int>(pyramid.world.hitEvents().size());
        }
        EXPECT_GE(hits, 4); // the balls, at least
    }
}

// A job system that runs every piece at once inside enqueue, last piece first, each as the
// worker after the last one's (pieces of minRange items): the order and the worker of every
// piece as unlike the world's own pool's as it gets, and the same on every run, so what a
// stage gathers from its workers must not depend on either.
struct ReversedJobs {
    int workers = 3;
    static void* enqueue(TaskFunction task, int itemCount, int minRange, void* taskContext,
                         void* userContext) {
        const auto& jobs = *static_cast<const ReversedJobs*>(userContext);
        const int piece = std::max(minRange, 1);
        int worker = 0;
        for (int begin = (itemCount - 1) / piece * piece; begin >= 0; begin -= piece) {
            task(begin, std::min(begin + piece, itemCount), worker, taskContext);
            worker = (worker + 1) % jobs.workers;
        }
        return nullptr;
    }
    static void finish(void* /*userTask*/, void* /*userContext*/) {
        ADD_FAILURE() << "enqueue ran every piece: finish is not called";
    }
};

TEST(WorldThreads, PiecesRunInAnyOrderOnAnyWorkerGiveTheSameSteps) {
    for (const Case& c : kCases) {
        ReversedJobs jobs;
        WorldDef def = threadedDef(jobs.workers, 8, c.mode);
        def.enqueueTask = ReversedJobs::enqueue;
        def.finishTask = ReversedJobs::finish;
        def.userTaskContext = &jobs;
        EXPECT_EQ(run(def, c.build, c.steps), run(threadedDef(1, 8, c.mode), c.build, c.steps))
            << c.name;
    }
}

TEST(WorldThreads, TheDefIsChecked) {
    E2D_EXPECT_ERROR(World(WorldDef{.workerCount = 0}),
                     "physics::World::World(): def.workerCount must be in [1, 64], got 0");
    E2D_EXPECT_ERROR(World(WorldDef{.workerCount = 65}),
                     "physics::World::World(): def.workerCount must be in [1, 64], got 65");
    E2D_EXPECT_ERROR(World(WorldDef{.minSplitWork = -1}),
                     "physics::World::World(): def.minSplitWork must be >= 0, got -1");
    E2D_EXPECT_ERROR(World(WorldDef{.enqueueTask = JobSystem::enqueue}),
                     "physics::World::World(): def.enqueueTask and def.finishTask must both be set "
                     "or both be null, got only enqueueTask");
    E2D_EXPECT_ERROR(World(WorldDef{.simdLanes = 16}),
                     "physics::World::World(): def.simdLanes must be 4 or 8, got 16");
}

// The world's own threads start and stop with it, and a moved world keeps them.
TEST(WorldThreads, AMovedWorldKeepsItsThreads) {
    World first(threadedDef(2, 8));
    Scene s{std::move(first), {}};
    buildPile(s);
    for (int i = 0; i < 10; ++i) {
        s.world.step(kStep);
    }
    EXPECT_GT(s.world.transform(s.bodies.back()).p.y, 0.0f);
}

} // namespace
} // namespace e2d::physics::test
