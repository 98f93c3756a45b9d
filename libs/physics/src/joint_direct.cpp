// SPDX-License-Identifier: MIT
// The direct solve of the joints (SolverDef::jointSolver Direct): every rigid row of a joint
// component at once, K dlambda = -r with K = J M^-1 J^T, factored by sparse block LDL^T in
// minimum-degree order. A chain or a tree eliminates leaf first without fill (Baraff 1996's
// linear-time factorisation, here over the joints: a joint's neighbours are the joints sharing
// one of its bodies); closed loops (a scissor lift) fill in, and are solved exactly too. The
// velocity solve (r = J v + bias) follows each Gauss-Seidel pass of the sub-steps; the position
// passes (r = C) linearise at the current positions (Newton steps), so a few passes remove
// errors that a Gauss-Seidel sweep would take one link per pass to move along a chain.
// Everything goes component by component (JointComponents), in slot order, so the result is
// the same bits whatever order the step keeps its bodies and joints in.
#include "joint_solver.hpp"

#include <e2d/physics/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace e2d::physics::detail {

namespace {

using Block = JointDirectScratch::Block;

// One rigid row: the motion of B's side minus A's along it (linear part per body, angular
// part), and its error.
struct RowJ {
    Vec2 linA;
    float angA;
    Vec2 linB;
    float angB;
};

// The rows of joint j at the states' current positions (0 to 3), their errors c and, for
// the velocity solve, the accumulated impulse each one adds to (`acc`) and whether that one
// stays >= 0 (a limit). Position rows: a limit only when violated, its error capped (a bounded
// push-out). Velocity rows: a revolute joint's nearer limit once it is within the angular slop
// or pushing, signed so that c >= 0 is allowed. A limit's row is always the joint's last.
int jointRows(Joint& j, const BodyState& a, const BodyState& b, bool velocity, bool released,
              RowJ rows[3], float c[3], float* acc[3], bool oneSided[3], JointErrors& worst) {
    int n = 0;
    auto add = [&](RowJ row, float C, float* accumulated, bool limit) {
        rows[n] = row;
        c[n] = C;
        acc[n] = accumulated;
        oneSided[n++] = limit;
    };
    auto point = [&](const JointFrame& f) {
        add({{-1.0f, 0.0f}, f.rA.y, {1.0f, 0.0f}, -f.rB.y}, f.d.x, &j.linearImpulse.x, false);
        add({{0.0f, -1.0f}, -f.rA.x, {0.0f, 1.0f}, f.rB.x}, f.d.y, &j.linearImpulse.y, false);
        worst.linear = std::max(worst.linear, length(f.d));
    };
    auto angle = [&](float C, float* accumulated) {
        add({{0.0f, 0.0f}, -1.0f, {0.0f, 0.0f}, 1.0f}, C, accumulated, false);
        worst.angular = std::max(worst.angular, std::abs(C));
    };
    auto slide = [&](Vec2 dir, float l1, float l2, float C, float* accumulated) {
        add({-dir, -l1, dir, l2}, C, accumulated, false);
    };
    switch (j.type) {
    case JointType::Motor:
    case JointType::Mouse:
        break;
    case JointType::Distance: {
        const JointFrame f = currentFrame(j, a, b);
        const float len = length(f.d);
        if (!j.enableSpring && !j.enableLimit && len > 0.0f) {
            const float C = std::clamp(len - j.length, -kMaxLinearCorrection, kMaxLinearCorrection);
            const Vec2 u = (1.0f / len) * f.d;
            slide(u, cross(f.rA, u), cross(f.rB, u), C, &j.springImpulse);
            worst.linear = std::max(worst.linear, std::abs(C));
        } else if (!velocity && j.enableLimit && len > 0.0f) {
            const float C = pastLimit(len, std::max(j.minLength, kLinearSlop), j.maxLength,
                                      kMaxLinearCorrection);
            if (C != 0.0f) {
                const Vec2 u = (1.0f / len) * f.d;
                slide(u, cross(f.rA, u), cross(f.rB, u), C, nullptr);
                worst.linear = std::max(worst.linear, std::abs(C));
            }
        }
        break;
    }
    case JointType::Revolute:
        point(currentFrame(j, a, b));
        if (j.enableLimit && !velocity) {
            const float C =
                pastLimit(currentAngle(j, a, b), j.lower, j.upper, kMaxAngularCorrection);
            if (C != 0.0f) {
                angle(C, nullptr);
            }
        } else if (j.enableLimit && j.lower < j.upper && !released) {
            const float value = currentAngle(j, a, b);
            const bool lowerSide = value - j.lower <= j.upper - value;
            const float side = lowerSide ? 1.0f : -1.0f;
            const float C = lowerSide ? value - j.lower : j.upper - value;
            float* impulse = lowerSide ? &j.lowerImpulse : &j.upperImpulse;
            if (C < kAngularSlop || *impulse > 0.0f) {
                add({{0.0f, 0.0f}, -side, {0.0f, 0.0f}, side}, C, impulse, true);
            }
        }
        break;
    case JointType::Weld:
        if (j.hertz == 0.0f) {
            point(currentFrame(j, a, b));
        }
        if (j.angularHertz == 0.0f) {
            angle(currentAngle(j, a, b), &j.angularImpulse);
        }
        break;
    case JointType::Prismatic:
    case JointType::Wheel: {
        const SlideFrame s = currentSlide(j, a, b);
        const float perp = dot(s.perp, s.f.d);
        slide(s.perp, s.s1, s.s2, perp,
              j.type == JointType::Prismatic ? &j.linearImpulse.x : &j.perpImpulse);
        worst.linear = std::max(worst.linear, std::abs(perp));
        if (j.type == JointType::Prismatic) {
            angle(currentAngle(j, a, b), &j.linearImpulse.y);
        }
        if (j.enableLimit && !velocity) {
            const float C = pastLimit(dot(s.axis, s.f.d), j.lower, j.upper, kMaxLinearCorrection);
            if (C != 0.0f) {
                slide(s.axis, s.a1, s.a2, C, nullptr);
                worst.linear = std::max(worst.linear, std::abs(C));
            }
        } else if (j.enableLimit && !released) {
            const float value = dot(s.axis, s.f.d);
            if (j.lower == j.upper) {
                // A locked slider (an actuator held): an equality row. Its impulse goes to the
                // spring's, unused without a spring and cleared at every step's prepare, so the
                // sub-steps warm start it and the limit rows' own stay >= 0.
                if (!j.enableSpring) {
                    slide(s.axis, s.a1, s.a2, value - j.lower, &j.springImpulse);
                }
            } else {
                const bool lowerSide = value - j.lower <= j.upper - value;
                const float side = lowerSide ? 1.0f : -1.0f;
                const float C = lowerSide ? value - j.lower : j.upper - value;
                float* impulse = lowerSide ? &j.lowerImpulse : &j.upperImpulse;
                if (C < kLinearSlop || *impulse > 0.0f) {
                    add({-side * s.axis, -side * s.a1, side * s.axis, side * s.a2}, C, impulse,
                        true);
                }
            }
        }
        break;
    }
    }
    return n;
}

// Row r of one side times that side's inverse mass times row s of the same side.
inline double coupling(Vec2 l1, float a1, Vec2 l2, float a2, Vec2 invMass, float invInertia) {
    return double(l1.x) * invMass.x * l2.x + double(l1.y) * invMass.y * l2.y +
           double(a1) * invInertia * a2;
}

Block mul(const Block& x, const Block& y) {
    Block r{};
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            r[3 * i + k] = x[3 * i] * y[k] + x[3 * i + 1] * y[3 + k] + x[3 * i + 2] * y[6 + k];
        }
    }
    return r;
}
Block transposed(const Block& x) { return {x[0], x[3], x[6], x[1], x[4], x[7], x[2], x[5], x[8]}; }
// The relative damping of each row of K (a Levenberg-Marquardt damping): redundant rows (a
// chain pulled straight between two fixed ends, closed loops) make K singular, and this keeps
// their share of an inconsistent error finite. The equality rows take kRegularization of their
// own diagonal; a limit's row only kLimitRegularization, a guard against round-off. A limit's
// row must not be damped like the others: on a long limited arm the root limit's effective
// inverse inertia (the whole arm's about the root, 1 / 33 kg m^2 for limited_arm_20) is the
// small difference of its own diagonal (one link's, 1 / 0.001) and the point rows' share,
// 30 000 times smaller, so 1e-3 of its diagonal is 30 times the answer.
constexpr double kRegularization = 1e-3;
constexpr double kLimitRegularization = 1e-9;

// x^-1 of a symmetric positive definite 3x3 (its padding rows are the identity).
Block inverse(const Block& x) {
    const double c00 = x[4] * x[8] - x[5] * x[7];
    const double c01 = x[5] * x[6] - x[3] * x[8];
    const double c02 = x[3] * x[7] - x[4] * x[6];
    double det = x[0] * c00 + x[1] * c01 + x[2] * c02;
    det = det != 0.0 ? 1.0 / det : 0.0;
    return {det * c00, det * (x[2] * x[7] - x[1] * x[8]), det * (x[1] * x[5] - x[2] * x[4]),
            det * c01, det * (x[0] * x[8] - x[2] * x[6]), det * (x[2] * x[3] - x[0] * x[5]),
            det * c02, det * (x[1] * x[6] - x[0] * x[7]), det * (x[0] * x[4] - x[1] * x[3])};
}
void mulVec(const Block& x, const double v[3], double out[3]) {
    for (int i = 0; i < 3; ++i) {
        out[i] = x[3 * i] * v[0] + x[3 * i + 1] * v[1] + x[3 * i + 2] * v[2];
    }
}
// mulVec(transposed(x), v, out) without the copy (the same products and sums).
void mulTransposedVec(const Block& x, const double v[3], double out[3]) {
    for (int i = 0; i < 3; ++i) {
        out[i] = x[i] * v[0] + x[3 + i] * v[1] + x[6 + i] * v[2];
    }
}
// mul(transposed(x), y) without the copy (the same products and sums).
Block mulTransposed(const Block& x, const Block& y) {
    Block r{};
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            r[3 * i + k] = x[i] * y[k] + x[3 + i] * y[3 + k] + x[6 + i] * y[6 + k];
        }
    }
    return r;
}

// Adds x to block (p, q) of the remaining matrix.
void addBlock(JointDirectScratch& w, std::size_t p, int q, const Block& x) {
    for (auto& e : w.adjacency[p]) {
        if (e.node == q) {
            for (std::size_t i = 0; i < 9; ++i) {
                e.block[i] += x[i];
            }
            return;
        }
    }
    w.adjacency[p].push_back({q, x});
}

// Solves per velocity pass at most: a limit that would pull is released and the rest solved
// again.
constexpr int kActiveSetRounds = 3;
// The factorisation gives up past this much work per joint (the squares of the neighbour
// counts at elimination): a chain or tree costs 4 to 10, the scissor lift 12, a 20 x 20 net
// far more.
constexpr std::size_t kWorkPerJoint = 64;

// Sorts w.bodyJoints (body, joint) by body then joint. They were listed in increasing joint,
// so a bucket sort over the bodies' range gives the same order; a component's bodies are most
// often a narrow range (a chain's, a ragdoll's), else std::sort.
void sortBodyJoints(JointDirectScratch& w) {
    if (w.bodyJoints.empty()) {
        return;
    }
    int low = w.bodyJoints.front().first;
    int high = low;
    for (const auto& entry : w.bodyJoints) {
        low = std::min(low, entry.first);
        high = std::max(high, entry.first);
    }
    const auto range = static_cast<std::size_t>(high - low) + 1;
    if (range > 4 * w.bodyJoints.size()) {
        std::sort(w.bodyJoints.begin(), w.bodyJoints.end());
        return;
    }
    w.unsortedBodyJoints.swap(w.bodyJoints);
    w.bodyJointStart.assign(range + 1, 0);
    for (const auto& entry : w.unsortedBodyJoints) {
        ++w.bodyJointStart[static_cast<std::size_t>(entry.first - low) + 1];
    }
    for (std::size_t b = 1; b <= range; ++b) {
        w.bodyJointStart[b] += w.bodyJointStart[b - 1];
    }
    w.bodyJoints.resize(w.unsortedBodyJoints.size());
    for (const auto& entry : w.unsortedBodyJoints) {
        int& at = w.bodyJointStart[static_cast<std::size_t>(entry.first - low)];
        w.bodyJoints[static_cast<std::size_t>(at++)] = entry;
    }
}

// Builds the rows of the joints `order` and their matrix K = J M^-1 J^T (diagonal blocks and
// the blocks of joints sharing a body); w.rhs gets -C. Returns the errors met.
JointErrors assemble(std::span<Joint> joints, std::span<const int> order,
                     std::span<const BodyState> states, bool velocity, JointDirectScratch& w) {
    const std::size_t n = order.size();
    w.rows.resize(n);
    w.rowCount.resize(n);
    w.rhs.resize(n);
    w.error.resize(n);
    w.diag.resize(n);
    w.adjacency.resize(n);
    for (auto& list : w.adjacency) {
        list.clear();
    }
    w.bodyJoints.clear();
    w.componentKey = n > 0 ? order.front() : -1;
    w.componentBodies.resize(n);
    JointErrors worst;
    const BodyState fixedState{};
    auto stateOf = [&](int index) -> const BodyState& {
        return index < 0 ? fixedState : states[static_cast<std::size_t>(index)];
    };
    for (std::size_t p = 0; p < n; ++p) {
        Joint& j = joints[static_cast<std::size_t>(order[p])];
        w.componentBodies[p] = {j.indexA, j.indexB};
        float c[3] = {0.0f, 0.0f, 0.0f};
        JointDirectScratch::Rows& r = w.rows[p];
        RowJ rows[3];
        const bool released = velocity && w.released[p] != 0;
        const int count = jointRows(j, stateOf(j.indexA), stateOf(j.indexB), velocity, released,
                                    rows, c, r.acc, r.oneSided, worst);
        w.rowCount[p] = count;
        for (int i = 0; i < 3; ++i) {
            r.linA[i] = i < count ? rows[i].linA : Vec2{0.0f, 0.0f};
            r.angA[i] = i < count ? rows[i].angA : 0.0f;
            r.linB[i] = i < count ? rows[i].linB : Vec2{0.0f, 0.0f};
            r.angB[i] = i < count ? rows[i].angB : 0.0f;
            w.error[p][static_cast<std::size_t>(i)] = i < count ? c[i] : 0.0f;
            w.rhs[p][static_cast<std::size_t>(i)] = i < count ? -double(c[i]) : 0.0;
        }
        // The joint's own block: both sides' couplings; padding rows are the identity.
        Block d{};
        for (int i = 0; i < 3; ++i) {
            for (int k = 0; k < 3; ++k) {
                if (i < count && k < count) {
                    d[static_cast<std::size_t>(3 * i + k)] =
                        coupling(r.linA[i], r.angA[i], r.linA[k], r.angA[k], j.invMassA,
                                 j.invInertiaA) +
                        coupling(r.linB[i], r.angB[i], r.linB[k], r.angB[k], j.invMassB,
                                 j.invInertiaB);
                } else {
                    d[static_cast<std::size_t>(3 * i + k)] = i == k ? 1.0 : 0.0;
                }
            }
        }
        // The damping (see kRegularization); a row with no motion at all (both sides fixed)
        // is padding. A limit is a velocity row that stays >= 0, or a position row with no
        // accumulated impulse.
        for (int i = 0; i < count; ++i) {
            double& x = d[static_cast<std::size_t>(4 * i)];
            x = x > 0.0 ? x * (1.0 + kRegularization) : 1.0;
        }
        // A limit is the last row (jointRows()).
        if (count > 0 && (r.oneSided[count - 1] || r.acc[count - 1] == nullptr)) {
            double& x = d[static_cast<std::size_t>(4 * (count - 1))];
            x *= (1.0 + kLimitRegularization) / (1.0 + kRegularization);
        }
        w.diag[p] = d;
        for (int s : {j.indexA, j.indexB}) {
            if (s >= 0) {
                w.bodyJoints.push_back({s, static_cast<int>(p)});
            }
        }
    }
    // The joints of each moving body, to find which joints share one.
    sortBodyJoints(w);
    // Off-diagonal blocks: joints p and q sharing body s couple through it.
    auto side = [&](std::size_t p, int s, Vec2(&lin)[3], float(&ang)[3], Vec2& invMass,
                    float& invInertia) {
        const Joint& j = joints[static_cast<std::size_t>(order[p])];
        const JointDirectScratch::Rows& r = w.rows[p];
        const bool isA = j.indexA == s;
        for (int i = 0; i < 3; ++i) {
            lin[i] = isA ? r.linA[i] : r.linB[i];
            ang[i] = isA ? r.angA[i] : r.angB[i];
        }
        invMass = isA ? j.invMassA : j.invMassB;
        invInertia = isA ? j.invInertiaA : j.invInertiaB;
    };
    for (std::size_t first = 0; first < w.bodyJoints.size();) {
        const int s = w.bodyJoints[first].first;
        std::size_t end = first + 1;
        while (end < w.bodyJoints.size() && w.bodyJoints[end].first == s) {
            ++end;
        }
        for (std::size_t x = first; x < end; ++x) {
            for (std::size_t y = x + 1; y < end; ++y) {
                const auto p = static_cast<std::size_t>(w.bodyJoints[x].second);
                const auto q = static_cast<std::size_t>(w.bodyJoints[y].second);
                Vec2 linP[3], linQ[3], invMass;
                float angP[3], angQ[3], invInertia;
                side(p, s, linP, angP, invMass, invInertia);
                side(q, s, linQ, angQ, invMass, invInertia);
                Block k{};
                for (int i = 0; i < 3; ++i) {
                    for (int m = 0; m < 3; ++m) {
                        k[static_cast<std::size_t>(3 * i + m)] =
                            coupling(linP[i], angP[i], linQ[m], angQ[m], invMass, invInertia);
                    }
                }
                addBlock(w, p, static_cast<int>(q), k);
                addBlock(w, q, static_cast<int>(p), transposed(k));
            }
        }
        first = end;
    }
    // Each row's blocks by joint: the factorisation visits them in this order, which the
    // bodies' order must not decide.
    // (A chain's or a tree's rows have one or two blocks, most often in order already: the
    // check is what a sort call would cost for them.)
    const auto byJoint = [](const JointDirectScratch::Entry& x,
                            const JointDirectScratch::Entry& y) { return x.node < y.node; };
    for (std::size_t p = 0; p < n; ++p) {
        auto& list = w.adjacency[p];
        if (!std::is_sorted(list.begin(), list.end(), byJoint)) {
            std::sort(list.begin(), list.end(), byJoint);
        }
    }
    return worst;
}

// LDL^T of the assembled K in minimum-degree order (ties: the lower index, deterministic).
// False, leaving the factor unusable, once the work passes kWorkPerJoint per joint (a large
// net: Gauss-Seidel is cheaper there).
bool factor(JointDirectScratch& w) {
    const std::size_t n = w.diag.size();
    w.order.clear();
    w.inverseDiag.resize(n);
    w.factor.resize(n);
    // The queue holds (degree, joint) for every joint left, with its current degree (a joint's
    // degree changes only when a neighbour is eliminated, and then it is pushed again), so the
    // least valid entry is the least degree, ties the lower index.
    // The order depends on the joints' bodies alone (the blocks' pattern, fill-in included,
    // not their values): a component whose bodies are those of its last factorisation replays
    // that order instead.
    const std::greater<std::pair<int, int>> later;
    JointDirectScratch::KnownOrder& known = w.knownOrders[w.componentKey];
    const bool replay = known.bodies == w.componentBodies;
    std::size_t replayed = 0;
    w.eliminated.assign(n, 0);
    w.queue.clear();
    if (!replay) {
        for (std::size_t p = 0; p < n; ++p) {
            w.queue.emplace_back(static_cast<int>(w.adjacency[p].size()), static_cast<int>(p));
        }
        std::make_heap(w.queue.begin(), w.queue.end(), later);
    }
    auto next = [&]() -> int {
        if (replay) {
            return replayed < known.order.size() ? known.order[replayed++] : -1;
        }
        while (!w.queue.empty()) {
            std::pop_heap(w.queue.begin(), w.queue.end(), later);
            const auto [degree, p] = w.queue.back();
            w.queue.pop_back();
            const auto i = static_cast<std::size_t>(p);
            if (w.eliminated[i] == 0 && static_cast<std::size_t>(degree) == w.adjacency[i].size()) {
                return p;
            }
        }
        return -1;
    };
    // The work of an elimination grows with the square of its neighbours: budget that.
    const std::size_t budget = kWorkPerJoint * n + 64;
    std::size_t work = 0;
    for (int next_p = next(); next_p >= 0; next_p = next()) {
        const auto p = static_cast<std::size_t>(next_p);
        w.eliminated[p] = 1;
        w.order.push_back(static_cast<int>(p));
        const Block dInv = inverse(w.diag[p]);
        w.inverseDiag[p] = dInv;
        auto& neighbours = w.factor[p];
        neighbours.assign(w.adjacency[p].begin(), w.adjacency[p].end()); // (i, A_pi)
        work += neighbours.size() * neighbours.size();
        if (work > budget) {
            return false;
        }
        // Schur complement: A_ik -= A_ip D^-1 A_pk for the remaining neighbours i, k.
        for (const auto& ei : neighbours) {
            const auto i = static_cast<std::size_t>(ei.node);
            auto& list = w.adjacency[i];
            list.erase(std::remove_if(list.begin(), list.end(),
                                      [&](const JointDirectScratch::Entry& e) {
                                          return e.node == static_cast<int>(p);
                                      }),
                       list.end());
            const Block left = mulTransposed(ei.block, dInv);
            for (const auto& ek : neighbours) {
                const Block update = mul(left, ek.block);
                if (ek.node == ei.node) {
                    for (std::size_t m = 0; m < 9; ++m) {
                        w.diag[i][m] -= update[m];
                    }
                } else {
                    Block neg;
                    for (std::size_t m = 0; m < 9; ++m) {
                        neg[m] = -update[m];
                    }
                    addBlock(w, i, ek.node, neg);
                }
            }
        }
        for (const auto& ei : neighbours) {
            if (!replay) {
                w.queue.emplace_back(
                    static_cast<int>(w.adjacency[static_cast<std::size_t>(ei.node)].size()),
                    ei.node);
                std::push_heap(w.queue.begin(), w.queue.end(), later);
            }
        }
    }
    if (!replay) {
        known.bodies = w.componentBodies;
        known.order = w.order;
    }
    return true;
}

// x = K^-1 rhs with the factor (rhs is overwritten): forward b_i -= A_ip D_p^-1 b_p, then
// backward x_p = D_p^-1 (b_p - sum A_pi x_i).
void solveFactored(JointDirectScratch& w) {
    for (int pi : w.order) {
        const auto p = static_cast<std::size_t>(pi);
        double z[3];
        mulVec(w.inverseDiag[p], w.rhs[p].data(), z);
        for (const auto& e : w.factor[p]) {
            double u[3];
            mulTransposedVec(e.block, z, u);
            for (std::size_t m = 0; m < 3; ++m) {
                w.rhs[static_cast<std::size_t>(e.node)][m] -= u[m];
            }
        }
    }
    w.solution.resize(w.order.size());
    for (auto it = w.order.rbegin(); it != w.order.rend(); ++it) {
        const auto p = static_cast<std::size_t>(*it);
        double b[3] = {w.rhs[p][0], w.rhs[p][1], w.rhs[p][2]};
        for (const auto& e : w.factor[p]) {
            double u[3];
            mulVec(e.block, w.solution[static_cast<std::size_t>(e.node)].data(), u);
            for (std::size_t m = 0; m < 3; ++m) {
                b[m] -= u[m];
            }
        }
        mulVec(w.inverseDiag[p], b, w.solution[p].data());
    }
}

// The impulse `lambda` of joint p's rows: B gets +J_B^T lambda, A +J_A^T lambda (linear
// impulses, or motions when `move`).
void applyRows(const Joint& j, const JointDirectScratch::Rows& r, int count, const double* lambda,
               std::span<BodyState> states, bool move) {
    Vec2 pA{0.0f, 0.0f}, pB{0.0f, 0.0f};
    float lA = 0.0f, lB = 0.0f;
    for (int i = 0; i < count; ++i) {
        const auto l = static_cast<float>(lambda[i]);
        pA += l * r.linA[i];
        lA += l * r.angA[i];
        pB += l * r.linB[i];
        lB += l * r.angB[i];
    }
    auto apply = [&](int index, Vec2 invMass, float invInertia, Vec2 p, float l) {
        if (index < 0) {
            return;
        }
        BodyState& s = states[static_cast<std::size_t>(index)];
        if (move) {
            s.deltaPosition += invMass * p;
            s.deltaRotation = integrateRotation(s.deltaRotation, invInertia * l);
        } else {
            s.linearVelocity += invMass * p;
            s.angularVelocity += invInertia * l;
        }
    };
    apply(j.indexA, j.invMassA, j.invInertiaA, pA, lA);
    apply(j.indexB, j.invMassB, j.invInertiaB, pB, lB);
}

// Whether component `slots` with `loops` independent closed loops is left to Gauss-Seidel:
// tooLoopy(), or its factorisation gave up earlier this step.
bool denseComponent(const JointDirectScratch& w, std::span<const int> slots, int loops) {
    return tooLoopy(slots.size(), static_cast<std::size_t>(loops)) ||
           std::find(w.denseComponents.begin(), w.denseComponents.end(), slots.front()) !=
               w.denseComponents.end();
}

// One Newton position pass over a component. True when every error was within the slops
// before the pass (nothing moved).
bool projectComponent(std::span<Joint> joints, std::span<const int> slots,
                      std::span<BodyState> states, JointDirectScratch& w) {
    w.released.assign(slots.size(), 0);
    const JointErrors worst = assemble(joints, slots, states, false, w);
    if (worst.linear <= kLinearSlop && worst.angular <= kAngularSlop) {
        return true;
    }
    if (!factor(w)) {
        w.denseComponents.push_back(slots.front());
        return solveJointPositions(joints, slots, states);
    }
    solveFactored(w);
    for (std::size_t p = 0; p < slots.size(); ++p) {
        applyRows(joints[static_cast<std::size_t>(slots[p])], w.rows[p], w.rowCount[p],
                  w.solution[p].data(), states, true);
    }
    return false;
}

// rhs = -(J v + bias) of every assembled row: the rows' velocities to zero, a limit not
// reached yet only stopped at it (speculative), position errors left to the projection (rigid
// rows: the softness's bias, 0 by default). w.limits gets the limit rows.
void velocityRhs(std::span<Joint> joints, std::span<const int> slots,
                 std::span<const BodyState> states, const JointStep& step, const Softness& soft,
                 JointDirectScratch& w) {
    const BodyState fixedState{};
    auto stateOf = [&](int index) -> const BodyState& {
        return index < 0 ? fixedState : states[static_cast<std::size_t>(index)];
    };
    w.limits.clear();
    for (std::size_t p = 0; p < slots.size(); ++p) {
        const Joint& j = joints[static_cast<std::size_t>(slots[p])];
        const JointDirectScratch::Rows& r = w.rows[p];
        const BodyState& a = stateOf(j.indexA);
        const BodyState& b = stateOf(j.indexB);
        for (int i = 0; i < w.rowCount[p]; ++i) {
            const float Cdot = dot(r.linA[i], a.linearVelocity) + r.angA[i] * a.angularVelocity +
                               dot(r.linB[i], b.linearVelocity) + r.angB[i] * b.angularVelocity;
            const float C = w.error[p][static_cast<std::size_t>(i)];
            const float bias = r.oneSided[i] && C > 0.0f ? C * step.invH : soft.biasRate * C;
            w.rhs[p][static_cast<std::size_t>(i)] = -double(Cdot + bias);
            if (r.oneSided[i]) {
                w.limits.emplace_back(static_cast<int>(p), i);
            }
        }
    }
}

// Adds the impulses w.solution to the joints' accumulated ones (a limit's kept >= 0) and to the
// bodies.
void applyVelocitySolution(std::span<Joint> joints, std::span<const int> slots,
                           std::span<BodyState> states, JointDirectScratch& w) {
    for (std::size_t p = 0; p < slots.size(); ++p) {
        Joint& j = joints[static_cast<std::size_t>(slots[p])];
        JointDirectScratch::Rows& r = w.rows[p];
        double* lambda = w.solution[p].data();
        for (int i = 0; i < w.rowCount[p]; ++i) {
            if (r.oneSided[i] && *r.acc[i] + lambda[i] < 0.0) {
                lambda[i] = -double(*r.acc[i]); // a stop never pulls
            }
            *r.acc[i] += static_cast<float>(lambda[i]);
        }
        applyRows(j, r, w.rowCount[p], lambda, states, false);
    }
}

// A group with more limits within reach than this solves them by the active set of
// solveActiveSet() (the dense complementarity problem grows with their square).
constexpr std::size_t kMaxDenseLimits = 64;

// Moves the limit rows of the assembled K (w.limits) out of it: their couplings to the other
// rows go to w.limitColumns (n x 3 per limit), their own to w.limitK (m x m), and their
// rows and columns in the blocks become padding; their rhs goes to w.limitVelocity (as J v +
// bias) and becomes 0.
void splitLimits(JointDirectScratch& w) {
    const std::size_t n = w.diag.size();
    const std::size_t m = w.limits.size();
    w.limitColumns.assign(m * n * 3, 0.0);
    w.limitK.assign(m * m, 0.0);
    w.limitVelocity.resize(m);
    w.limitOf.assign(n, -1); // a joint has one limit row at most (its nearer side)
    for (std::size_t l = 0; l < m; ++l) {
        w.limitOf[static_cast<std::size_t>(w.limits[l].first)] = static_cast<int>(l);
    }
    for (std::size_t l = 0; l < m; ++l) {
        const auto p = static_cast<std::size_t>(w.limits[l].first);
        const auto i = static_cast<std::size_t>(w.limits[l].second);
        double* column = &w.limitColumns[l * n * 3];
        w.limitVelocity[l] = -w.rhs[p][i];
        w.rhs[p][i] = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
            if (k != i) {
                column[3 * p + k] = w.diag[p][3 * k + i];
            }
        }
        w.limitK[l * m + l] = w.diag[p][4 * i];
        for (const auto& e : w.adjacency[p]) {
            const auto q = static_cast<std::size_t>(e.node);
            for (std::size_t c = 0; c < 3; ++c) {
                const double v = e.block[3 * i + c];
                const int other = w.limitOf[q];
                if (other >= 0 && static_cast<std::size_t>(
                                      w.limits[static_cast<std::size_t>(other)].second) == c) {
                    w.limitK[l * m + static_cast<std::size_t>(other)] = v;
                } else {
                    column[3 * q + c] = v;
                }
            }
        }
    }
    for (std::size_t l = 0; l < m; ++l) {
        const auto p = static_cast<std::size_t>(w.limits[l].first);
        const auto i = static_cast<std::size_t>(w.limits[l].second);
        for (std::size_t k = 0; k < 3; ++k) {
            w.diag[p][3 * i + k] = 0.0;
            w.diag[p][3 * k + i] = 0.0;
        }
        w.diag[p][4 * i] = 1.0;
        for (auto& e : w.adjacency[p]) {
            for (std::size_t c = 0; c < 3; ++c) {
                e.block[3 * i + c] = 0.0;
            }
            for (auto& back : w.adjacency[static_cast<std::size_t>(e.node)]) {
                if (back.node == static_cast<int>(p)) {
                    for (std::size_t r = 0; r < 3; ++r) {
                        back.block[3 * r + i] = 0.0;
                    }
                }
            }
        }
    }
}

double dotColumn(const double* column, const std::vector<std::array<double, 3>>& x) {
    double sum = 0.0;
    for (std::size_t p = 0; p < x.size(); ++p) {
        sum += column[3 * p] * x[p][0] + column[3 * p + 1] * x[p][1] + column[3 * p + 2] * x[p][2];
    }
    return sum;
}

// The velocity solve of a component whose assembled rows include limits (w.limits, at most
// kMaxDenseLimits): the other rows factored alone, the limits' Schur complement
// S = K_ll - K_lp K_pp^-1 K_pl and velocities q with the limits at rest, then the mixed
// problem's limit impulses x = acc + dlambda >= 0 with S dlambda + q >= 0, complementary
// (solveDenseLcp()), and the other rows' impulses back-substituted. False, changing nothing,
// when the factorisation gives up.
bool solveMixed(std::span<Joint> joints, std::span<const int> slots, std::span<BodyState> states,
                JointDirectScratch& w) {
    const std::size_t n = slots.size();
    const std::size_t m = w.limits.size();
    splitLimits(w);
    if (!factor(w)) {
        return false;
    }
    solveFactored(w); // the other rows with the limits at rest
    w.unlimited = w.solution;
    w.limitResponse.resize(m * n * 3);
    for (std::size_t k = 0; k < m; ++k) {
        const double* column = &w.limitColumns[k * n * 3];
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < 3; ++c) {
                w.rhs[p][c] = column[3 * p + c];
            }
        }
        solveFactored(w);
        double* response = &w.limitResponse[k * n * 3];
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < 3; ++c) {
                response[3 * p + c] = w.solution[p][c];
            }
        }
    }
    w.schur.resize(m * m);
    w.limitImpulse.resize(m);
    for (std::size_t l = 0; l < m; ++l) {
        const double* column = &w.limitColumns[l * n * 3];
        w.limitVelocity[l] += dotColumn(column, w.unlimited);
        for (std::size_t k = 0; k < m; ++k) {
            const double* response = &w.limitResponse[k * n * 3];
            double coupled = 0.0;
            for (std::size_t e = 0; e < 3 * n; ++e) {
                coupled += column[e] * response[e];
            }
            w.schur[l * m + k] = w.limitK[l * m + k] - coupled;
        }
        const auto& limit = w.limits[l];
        w.limitImpulse[l] = double(*w.rows[static_cast<std::size_t>(limit.first)]
                                        .acc[static_cast<std::size_t>(limit.second)]);
    }
    // In the accumulated impulses x: w = S (x - acc) + q.
    for (std::size_t l = 0; l < m; ++l) {
        for (std::size_t k = 0; k < m; ++k) {
            w.limitVelocity[l] -= w.schur[l * m + k] * w.limitImpulse[k];
        }
    }
    solveDenseLcp(static_cast<int>(m), w.schur, w.limitVelocity, w.limitImpulse,
                  static_cast<int>(4 * m + 8), w.lcp);
    // dlambda of the limits, then the other rows': unlimited - sum_k response_k dlambda_k.
    w.solution = w.unlimited;
    for (std::size_t k = 0; k < m; ++k) {
        const auto& limit = w.limits[k];
        const auto p = static_cast<std::size_t>(limit.first);
        const auto i = static_cast<std::size_t>(limit.second);
        const double delta = w.limitImpulse[k] - double(*w.rows[p].acc[i]);
        const double* response = &w.limitResponse[k * n * 3];
        for (std::size_t q = 0; q < n; ++q) {
            for (std::size_t c = 0; c < 3; ++c) {
                w.solution[q][c] -= response[3 * q + c] * delta;
            }
        }
        w.solution[p][i] = delta;
    }
    applyVelocitySolution(joints, slots, states, w);
    return true;
}

// The velocity solve of a component with many limits: a limit that would pull is released
// and the rest solved again (an active set; at most kActiveSetRounds solves). False, changing
// nothing, when its factorisation gives up.
bool solveActiveSet(std::span<Joint> joints, std::span<const int> slots,
                    std::span<BodyState> states, const JointStep& step, const Softness& soft,
                    JointDirectScratch& w) {
    for (int round = 0; round < kActiveSetRounds; ++round) {
        if (round > 0) {
            assemble(joints, slots, states, true, w);
            velocityRhs(joints, slots, states, step, soft, w);
        }
        if (!factor(w)) {
            return false;
        }
        solveFactored(w);
        bool pulls = false;
        for (std::size_t p = 0; p < slots.size(); ++p) {
            const JointDirectScratch::Rows& r = w.rows[p];
            for (int i = 0; i < w.rowCount[p]; ++i) {
                if (r.oneSided[i] && *r.acc[i] + w.solution[p][static_cast<std::size_t>(i)] < 0.0) {
                    w.released[p] = 1;
                    pulls = true;
                }
            }
        }
        if (!pulls) {
            break;
        }
    }
    applyVelocitySolution(joints, slots, states, w);
    return true;
}

// The velocity solve of one component; false, changing nothing, when its factorisation gives
// up (then marked dense for the step).
bool solveComponent(std::span<Joint> joints, std::span<const int> slots,
                    std::span<BodyState> states, const JointStep& step, bool useBias,
                    JointDirectScratch& w) {
    const Softness soft = rigidSoftness(step, useBias);
    w.released.assign(slots.size(), 0);
    assemble(joints, slots, states, true, w);
    velocityRhs(joints, slots, states, step, soft, w);
    const bool solved = !w.limits.empty() && w.limits.size() <= kMaxDenseLimits
                            ? solveMixed(joints, slots, states, w)
                            : solveActiveSet(joints, slots, states, step, soft, w);
    if (!solved) {
        w.denseComponents.push_back(slots.front());
    }
    return solved;
}

} // namespace

void projectJointComponents(std::span<Joint> joints, std::span<const int> order,
                            std::span<BodyState> states, int iterations, bool gaussSeidel,
                            JointDirectScratch& w) {
    findJointComponents(joints, order, states.size(), w.components);
    const JointComponents& components = w.components;
    for (std::size_t c = 0; c < components.size(); ++c) {
        const std::span<const int> slots = components.component(c);
        for (int i = 0; i < iterations; ++i) {
            const bool done = gaussSeidel || denseComponent(w, slots, components.loops[c])
                                  ? solveJointPositions(joints, slots, states)
                                  : projectComponent(joints, slots, states, w);
            if (done) {
                break;
            }
        }
    }
}

void solveJointsDirect(std::span<Joint> joints, std::span<const int> order,
                       std::span<BodyState> states, const JointStep& step, bool useBias,
                       JointDirectScratch& w) {
    // The loopy groups' joints are the Gauss-Seidel pass's alone (markLoopyJoints()).
    findJointComponents(joints, order, states.size(), w.components, true);
    const JointComponents& components = w.components;
    for (std::size_t c = 0; c < components.size(); ++c) {
        const std::span<const int> slots = components.component(c);
        if (!denseComponent(w, slots, components.loops[c])) {
            solveComponent(joints, slots, states, step, useBias, w);
        }
    }
}

} // namespace e2d::physics::detail
