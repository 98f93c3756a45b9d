// SPDX-License-Identifier: MIT
// Narrow phase: e2d SAT, e2d GJK/EPA and Box2D 2.4 on the same pairs, in one binary.
// Each case is an array of pairs, so branches and memory behave as in a real step; every
// iteration collides every pair once. Reported: ns per pair and the ratio to Box2D.
#include "ratio_reporter.hpp"

#include <e2d/physics/geometry.hpp>
#include <e2d/physics/manifold.hpp>

#include "broad_phase.hpp"

#include <box2d/b2_broad_phase.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace ph = e2d::physics;

constexpr int kPairsPerCase = 256;

// One shape in both engines' form.
struct Shape {
    bool circle = false;
    ph::Polygon polygon{};
    ph::Circle disc{};
    b2PolygonShape b2polygon{};
    b2CircleShape b2disc{};
};

struct Pair {
    int a = 0;
    int b = 0;
    ph::Transform xfA{};
    ph::Transform xfB{};
    b2Transform b2xfA{};
    b2Transform b2xfB{};
};

struct Case {
    std::string name;
    std::vector<Shape> shapes;
    std::vector<Pair> pairs;
    bool expectContact = true;
};

// Uniform float in [lo, hi) from the engine's raw bits, identical on every standard library.
struct Rng {
    std::mt19937 engine{12345u};
    float operator()(float lo, float hi) {
        return lo + (hi - lo) * static_cast<float>(engine() >> 8) * (1.0f / 16777216.0f);
    }
};

Shape polygonShape(const std::vector<ph::Vec2>& points) {
    Shape s;
    s.polygon = ph::makePolygon(points);
    std::vector<b2Vec2> b2points;
    for (int i = 0; i < s.polygon.count; ++i) {
        b2points.emplace_back(s.polygon.vertices[i].x, s.polygon.vertices[i].y);
    }
    s.b2polygon.Set(b2points.data(), static_cast<int32>(b2points.size()));
    return s;
}

Shape boxShape(float hx, float hy) {
    return polygonShape({{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}});
}

Shape circleShape(float radius) {
    Shape s;
    s.circle = true;
    s.disc = ph::Circle{{0.0f, 0.0f}, radius};
    s.b2disc.m_radius = radius;
    s.b2disc.m_p.SetZero();
    return s;
}

Pair makePair(int a, int b, ph::Vec2 pa, float angleA, ph::Vec2 pb, float angleB) {
    Pair p;
    p.a = a;
    p.b = b;
    p.xfA = {pa, ph::Rot::fromAngle(angleA)};
    p.xfB = {pb, ph::Rot::fromAngle(angleB)};
    p.b2xfA.Set({pa.x, pa.y}, angleA);
    p.b2xfB.Set({pb.x, pb.y}, angleB);
    return p;
}

std::vector<Case> makeCases() {
    Rng rng;
    std::vector<Case> cases;

    // A box resting on a box: B sits 1 cm into A, jittered by a millimetre.
    {
        Case c{"box_box_resting", {boxShape(0.5f, 0.5f)}, {}, true};
        for (int i = 0; i < kPairsPerCase; ++i) {
            c.pairs.push_back(makePair(0, 0, {0.0f, 0.0f}, 0.0f,
                                       {rng(-0.05f, 0.05f), 0.99f + rng(-0.001f, 0.001f)},
                                       rng(-0.01f, 0.01f)));
        }
        cases.push_back(std::move(c));
    }
    // Rotated boxes of different sizes, overlapping.
    {
        Case c{"box_box_rotated", {boxShape(0.5f, 0.5f), boxShape(1.0f, 0.25f)}, {}, true};
        for (int i = 0; i < kPairsPerCase; ++i) {
            c.pairs.push_back(makePair(0, 1, {0.0f, 0.0f}, rng(-3.14f, 3.14f),
                                       {rng(-0.6f, 0.6f), rng(-0.6f, 0.6f)}, rng(-3.14f, 3.14f)));
        }
        cases.push_back(std::move(c));
    }
    // Random 8-gons (8 points on a circle at sorted random angles), overlapping.
    {
        Case c{"ngon8_overlapping", {}, {}, true};
        for (int s = 0; s < 32; ++s) {
            const float radius = rng(0.3f, 1.0f);
            std::vector<ph::Vec2> points;
            for (int k = 0; k < 8; ++k) {
                const float angle = (static_cast<float>(k) + rng(0.1f, 0.9f)) * (6.2831853f / 8.0f);
                points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
            }
            c.shapes.push_back(polygonShape(points));
        }
        for (int i = 0; i < kPairsPerCase; ++i) {
            c.pairs.push_back(makePair(i % 32, (i * 7 + 3) % 32, {0.0f, 0.0f}, rng(-3.14f, 3.14f),
                                       {rng(-0.25f, 0.25f), rng(-0.25f, 0.25f)},
                                       rng(-3.14f, 3.14f)));
        }
        cases.push_back(std::move(c));
    }
    // Boxes 3 m apart: every routine should leave early.
    {
        Case c{"box_box_separated", {boxShape(0.5f, 0.5f)}, {}, false};
        for (int i = 0; i < kPairsPerCase; ++i) {
            const float angle = rng(0.0f, 6.2831853f);
            c.pairs.push_back(makePair(0, 0, {0.0f, 0.0f}, rng(-3.14f, 3.14f),
                                       {3.0f * std::cos(angle), 3.0f * std::sin(angle)},
                                       rng(-3.14f, 3.14f)));
        }
        cases.push_back(std::move(c));
    }
    // A circle against a box, overlapping.
    {
        Case c{"circle_polygon", {boxShape(0.5f, 0.5f), circleShape(0.3f)}, {}, true};
        for (int i = 0; i < kPairsPerCase; ++i) {
            const float angle = rng(0.0f, 6.2831853f);
            const float d = rng(0.3f, 0.7f);
            c.pairs.push_back(makePair(0, 1, {0.0f, 0.0f}, rng(-3.14f, 3.14f),
                                       {d * std::cos(angle), d * std::sin(angle)}, 0.0f));
        }
        cases.push_back(std::move(c));
    }
    // Two circles, overlapping.
    {
        Case c{"circle_circle", {circleShape(0.5f), circleShape(0.3f)}, {}, true};
        for (int i = 0; i < kPairsPerCase; ++i) {
            const float angle = rng(0.0f, 6.2831853f);
            const float d = rng(0.1f, 0.75f);
            c.pairs.push_back(makePair(0, 1, {0.0f, 0.0f}, 0.0f,
                                       {d * std::cos(angle), d * std::sin(angle)}, 0.0f));
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

const std::vector<Case>& cases() {
    static const std::vector<Case> all = makeCases();
    return all;
}

// Box2DWorld: Box2D's b2Collide* plus b2WorldManifold::Initialize, which turns Box2D 2.4's
// local manifold into what e2d's routines return (world normal, world points, separations);
// Box2D's contact solver does that per contact every step. Reported as its own column so the
// ratio to the bare b2Collide* call stays visible.
enum class Engine { Sat, GjkEpa, Box2D, Box2DWorld };

float radiusOf(const Shape& s) { return s.circle ? s.b2disc.m_radius : s.b2polygon.m_radius; }

int collideOnce(const Case& c, const Pair& p, Engine engine) {
    const Shape& a = c.shapes[static_cast<std::size_t>(p.a)];
    const Shape& b = c.shapes[static_cast<std::size_t>(p.b)];
    if (engine == Engine::Box2D || engine == Engine::Box2DWorld) {
        b2Manifold m;
        if (a.circle && b.circle) {
            b2CollideCircles(&m, &a.b2disc, p.b2xfA, &b.b2disc, p.b2xfB);
        } else if (b.circle) {
            b2CollidePolygonAndCircle(&m, &a.b2polygon, p.b2xfA, &b.b2disc, p.b2xfB);
        } else {
            b2CollidePolygons(&m, &a.b2polygon, p.b2xfA, &b.b2polygon, p.b2xfB);
        }
        if (engine == Engine::Box2DWorld && m.pointCount > 0) {
            b2WorldManifold wm;
            wm.Initialize(&m, p.b2xfA, radiusOf(a), p.b2xfB, radiusOf(b));
            benchmark::DoNotOptimize(wm);
        }
        benchmark::DoNotOptimize(m);
        return m.pointCount;
    }
    // Built in place (as a caller of the by-value API does), not default-constructed and then
    // assigned: that would zero and copy the 92-byte Manifold on every call, work the Box2D
    // path (which writes into an uninitialised b2Manifold) does not do.
    const ph::Manifold m = [&] {
        if (a.circle && b.circle) {
            return ph::collideCircles(a.disc, p.xfA, b.disc, p.xfB);
        }
        if (b.circle) {
            return ph::collidePolygonAndCircle(a.polygon, p.xfA, b.disc, p.xfB);
        }
        if (engine == Engine::Sat) {
            return ph::collidePolygons(a.polygon, p.xfA, b.polygon, p.xfB);
        }
        return ph::collidePolygonsGjkEpa(a.polygon, p.xfA, b.polygon, p.xfB);
    }();
    benchmark::DoNotOptimize(m);
    return m.pointCount;
}

void collideCase(benchmark::State& state, const Case* c, Engine engine) {
    for (auto _ : state) {
        for (const Pair& p : c->pairs) {
            collideOnce(*c, p, engine);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c->pairs.size()));
}

bool hasCircle(const Case& c) {
    for (const Shape& s : c.shapes) {
        if (s.circle) {
            return true;
        }
    }
    return false;
}

// Before timing anything: both engines must agree on whether each pair touches, or the
// comparison would be meaningless.
bool checkAgreement() {
    bool ok = true;
    for (const Case& c : cases()) {
        for (std::size_t i = 0; i < c.pairs.size(); ++i) {
            const int box2d = collideOnce(c, c.pairs[i], Engine::Box2D);
            const int sat = collideOnce(c, c.pairs[i], Engine::Sat);
            const int gjk = collideOnce(c, c.pairs[i], Engine::GjkEpa);
            const bool expected = c.expectContact;
            if ((box2d > 0) != expected || (sat > 0) != expected || (gjk > 0) != expected) {
                std::fprintf(stderr,
                             "%s pair %zu: contact points box2d=%d sat=%d gjk=%d, expected %s\n",
                             c.name.c_str(), i, box2d, sat, gjk, expected ? "contact" : "none");
                ok = false;
            }
        }
    }
    return ok;
}

// Broad phase: 10 000 boxes on a 100 x 100 grid (1 m apart, 0.7 m wide, so each one's fat box
// overlaps its neighbours' only when they swing towards each other), each oscillating about
// its cell with its own amplitude, frequency and phase. One benchmark iteration is one 60 Hz
// frame: every box reports its new box (e2d moveProxy, Box2D MoveProxy with the frame's
// displacement), then the engine finds the pairs. Both engines fatten by 0.1 m (kAabbMargin,
// b2_aabbExtension). What differs, as the engines allow:
// - Box2D also stretches a moved fat box along 4x the displacement (b2_aabbMultiplier); e2d
//   does not.
// - Box2D's UpdatePairs reports every overlapping pair of every moved proxy, old ones again,
//   to a callback (here: append to a vector); its b2ContactManager dedupes them later, outside
//   the broad phase. e2d keeps the pair set itself: updatePairs() reports only new pairs, and
//   prunePairs() (timed here, its World does it every step) drops pairs whose fat boxes
//   separated. So e2d's frame does strictly more bookkeeping.
constexpr int kGridSide = 100;
constexpr int kBoxCount = kGridSide * kGridSide;
constexpr float kFrameDt = 1.0f / 60.0f;

struct Mover {
    float baseX = 0.0f;
    float baseY = 0.0f;
    float ampX = 0.0f;
    float ampY = 0.0f;
    float omega = 0.0f;
    float phase = 0.0f;
};

std::vector<Mover> makeMovers() {
    Rng rng;
    std::vector<Mover> movers;
    movers.reserve(kBoxCount);
    for (int i = 0; i < kBoxCount; ++i) {
        Mover m;
        m.baseX = static_cast<float>(i % kGridSide);
        m.baseY = static_cast<float>(i / kGridSide);
        m.ampX = rng(0.0f, 0.4f);
        m.ampY = rng(0.0f, 0.4f);
        m.omega = rng(1.0f, 4.0f);
        m.phase = rng(0.0f, 6.2831853f);
        movers.push_back(m);
    }
    return movers;
}

constexpr float kBoxHalf = 0.35f;

// The tight box of mover `m` at frame `frame`, and its centre.
std::pair<float, float> moverCentre(const Mover& m, int frame) {
    const float t = static_cast<float>(frame) * kFrameDt;
    return {m.baseX + m.ampX * std::sin(m.omega * t + m.phase),
            m.baseY + m.ampY * std::cos(m.omega * t + m.phase)};
}

// The centres of every box for `frames` consecutive frames, computed before timing so both
// engines replay exactly the same motion and neither pays for the trigonometry.
struct Motion {
    int frames = 0;
    std::vector<float> x; // [frame * kBoxCount + box]
    std::vector<float> y;
};

const Motion& motion() {
    static const Motion all = [] {
        Motion m;
        m.frames = 240; // 4 s: every box goes through at least one full swing
        const std::vector<Mover> movers = makeMovers();
        m.x.resize(static_cast<std::size_t>(m.frames) * kBoxCount);
        m.y.resize(m.x.size());
        for (int f = 0; f < m.frames; ++f) {
            for (int i = 0; i < kBoxCount; ++i) {
                const auto [cx, cy] = moverCentre(movers[static_cast<std::size_t>(i)], f);
                const std::size_t k =
                    static_cast<std::size_t>(f) * kBoxCount + static_cast<std::size_t>(i);
                m.x[k] = cx;
                m.y[k] = cy;
            }
        }
        return m;
    }();
    return all;
}

void broadPhaseE2d(benchmark::State& state) {
    const Motion& mo = motion();
    ph::detail::BroadPhase bp;
    std::vector<int> keys(kBoxCount);
    for (int i = 0; i < kBoxCount; ++i) {
        const float cx = mo.x[static_cast<std::size_t>(i)];
        const float cy = mo.y[static_cast<std::size_t>(i)];
        keys[static_cast<std::size_t>(i)] =
            bp.createProxy({{cx - kBoxHalf, cy - kBoxHalf}, {cx + kBoxHalf, cy + kBoxHalf}},
                           ph::BodyType::Dynamic, ~std::uint64_t{0}, static_cast<std::uint64_t>(i));
    }
    auto accept = [](std::uint64_t, std::uint64_t) { return true; };
    bp.updatePairs(accept);
    std::int64_t newPairs = 0;
    std::int64_t reinserted = 0;
    int frame = 1;
    for (auto _ : state) {
        const std::size_t base = static_cast<std::size_t>(frame) * kBoxCount;
        for (int i = 0; i < kBoxCount; ++i) {
            const float cx = mo.x[base + static_cast<std::size_t>(i)];
            const float cy = mo.y[base + static_cast<std::size_t>(i)];
            reinserted +=
                bp.moveProxy(keys[static_cast<std::size_t>(i)],
                             {{cx - kBoxHalf, cy - kBoxHalf}, {cx + kBoxHalf, cy + kBoxHalf}})
                    ? 1
                    : 0;
        }
        bp.prunePairs();
        bp.updatePairs(accept);
        newPairs += static_cast<std::int64_t>(bp.newPairs().size());
        frame = frame + 1 < mo.frames ? frame + 1 : 1;
    }
    state.SetItemsProcessed(state.iterations() * kBoxCount);
    state.counters["pairs"] = static_cast<double>(bp.pairCount());
    // Tree quality after the last frame (sum of internal perimeters over the root's).
    state.counters["area_ratio"] = static_cast<double>(bp.tree(ph::BodyType::Dynamic).areaRatio());
    // Boxes that left their fat box and were reinserted into the tree, per frame.
    state.counters["moves_per_frame"] = benchmark::Counter(static_cast<double>(reinserted) /
                                                           static_cast<double>(state.iterations()));
    state.counters["new_pairs_per_frame"] =
        benchmark::Counter(static_cast<double>(newPairs) / static_cast<double>(state.iterations()));
}

struct Box2DPairRecorder {
    std::vector<std::pair<void*, void*>> pairs;
    void AddPair(void* a, void* b) { pairs.emplace_back(a, b); }
};

void broadPhaseBox2D(benchmark::State& state) {
    const Motion& mo = motion();
    b2BroadPhase bp;
    std::vector<int32> ids(kBoxCount);
    // userData is only compared, never dereferenced: the box index as a pointer-sized value.
    std::vector<char> tags(kBoxCount);
    for (int i = 0; i < kBoxCount; ++i) {
        const float cx = mo.x[static_cast<std::size_t>(i)];
        const float cy = mo.y[static_cast<std::size_t>(i)];
        b2AABB box;
        box.lowerBound.Set(cx - kBoxHalf, cy - kBoxHalf);
        box.upperBound.Set(cx + kBoxHalf, cy + kBoxHalf);
        ids[static_cast<std::size_t>(i)] = bp.CreateProxy(box, &tags[static_cast<std::size_t>(i)]);
    }
    Box2DPairRecorder recorder;
    bp.UpdatePairs(&recorder);
    std::int64_t reported = 0;
    int frame = 1;
    for (auto _ : state) {
        const std::size_t base = static_cast<std::size_t>(frame) * kBoxCount;
        const std::size_t previous =
            static_cast<std::size_t>(frame > 1 ? frame - 1 : mo.frames - 1) * kBoxCount;
        for (int i = 0; i < kBoxCount; ++i) {
            const std::size_t k = base + static_cast<std::size_t>(i);
            const std::size_t kp = previous + static_cast<std::size_t>(i);
            const float cx = mo.x[k];
            const float cy = mo.y[k];
            b2AABB box;
            box.lowerBound.Set(cx - kBoxHalf, cy - kBoxHalf);
            box.upperBound.Set(cx + kBoxHalf, cy + kBoxHalf);
            bp.MoveProxy(ids[static_cast<std::size_t>(i)], box,
                         b2Vec2(cx - mo.x[kp], cy - mo.y[kp]));
        }
        recorder.pairs.clear();
        bp.UpdatePairs(&recorder);
        reported += static_cast<std::int64_t>(recorder.pairs.size());
        frame = frame + 1 < mo.frames ? frame + 1 : 1;
    }
    state.SetItemsProcessed(state.iterations() * kBoxCount);
    state.counters["area_ratio"] = static_cast<double>(bp.GetTreeQuality());
    state.counters["reported_pairs_per_frame"] =
        benchmark::Counter(static_cast<double>(reported) / static_cast<double>(state.iterations()));
}

void registerAll() {
    benchmark::RegisterBenchmark("broadphase/10000_moving/box2d", broadPhaseBox2D)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("broadphase/10000_moving/e2d", broadPhaseE2d)
        ->Unit(benchmark::kMicrosecond);
    for (const Case& c : cases()) {
        const std::string base = "collide/" + c.name + "/";
        benchmark::RegisterBenchmark((base + "box2d").c_str(), collideCase, &c, Engine::Box2D);
        benchmark::RegisterBenchmark((base + "box2d_world").c_str(), collideCase, &c,
                                     Engine::Box2DWorld);
        benchmark::RegisterBenchmark((base + "e2d_sat").c_str(), collideCase, &c, Engine::Sat);
        if (!hasCircle(c)) { // circles use the direct routines whatever the algorithm
            benchmark::RegisterBenchmark((base + "e2d_gjk_epa").c_str(), collideCase, &c,
                                         Engine::GjkEpa);
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    if (!checkAgreement()) {
        std::fprintf(stderr, "e2d and Box2D disagree on which pairs touch; not benchmarking\n");
        return 1;
    }
    registerAll();
    // Items are pairs for collide/*, boxes (per frame) for broadphase/*.
    return e2d::bench::runWithRatios(argc, argv, "box2d",
                                     {"e2d_sat", "e2d_gjk_epa", "e2d", "box2d", "box2d_world"},
                                     "ns per item");
}
