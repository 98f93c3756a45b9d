// SPDX-License-Identifier: MIT
#pragma once

#include "contact_solver.hpp"
#include "contact_solver_wide.hpp"
#include "solver_body.hpp"

#include <span>
#include <vector>

// Simultaneous impacts on touching rows of elastic bodies, as a sequence of binary collisions
// (Newton's cradle).
//
// The velocity solve sees the contacts of a row struck at one end as one problem and moves
// the row as one body would: a cradle's striker bounces back and the row creeps forward
// together. A real row passes the impulse on: each pair collides in turn, the struck ball
// stops and the last leaves. So, for each row of touching elastic bodies struck this step,
// the impacts are resolved before the solve, on the velocities the step starts with, as
// binary collisions along each contact's normal with its restitution, contact by contact in
// the order the impulse travels (breadth first from the struck contacts), sweep after sweep
// until no contact of the row approaches; after the solve the row's bodies take that result
// in place of the merged one.
//
// Only rows the solve gets wrong are treated: a struck contact whose bodies touch no other
// movable elastic body is an ordinary pair impact (or one against a wall or the ground),
// which the solve's restitution already resolves exactly (to the bounce height, under
// gravity). Contacts without restitution never join a row: inelastic scenes, resting stacks
// and pyramids are untouched, and a step in which nothing elastic is struck costs one
// approach test per contact with restitution (none where there is none).
namespace e2d::physics::detail {

// How many times at most the sweeps go over a row's contacts. An elastic row of equal bodies
// needs one sweep (and one to find nothing left); unequal masses bounce back and forth a few
// times (a body twice as heavy striking two: two sweeps). Approaches below the restitution
// threshold are plastic, and a long plastic row converges only geometrically: what is left
// after this many sweeps is the next step's contact solve's, as before.
inline constexpr int kMaxImpactSweeps = 64;

struct Simulation;

// One worker's impact pass: plan() before the velocity solve, apply() after. Scratch and
// results are kept here between the two and reused step after step.
class ContactImpacts {
public:
    // Resolves the impacts on the struck rows among the step's contacts with restitution,
    // from s.states' velocities, which must still be the step's starting ones (the bodies
    // concerned not solved yet): the scalar solvers' constraints, or one block's restitution
    // list of the wide solver (s.constraintContacts and s.constraintBodies give their
    // contacts). dt: the step, seconds. Returns whether apply() has anything to write.
    bool plan(const Simulation& s, std::span<const ContactConstraint> constraints, float dt);
    bool plan(const Simulation& s, std::span<const WideRestitution> list, float dt);
    // Writes the planned velocities of the struck rows' bodies into s.states, after the
    // velocity solve (the positions it integrated this step stay), and
    // takes the row contacts' impulses out of next step's warm start: an impact's impulse is
    // not a load that persists, and warm-started it pushed the row apart again (the striker
    // back at 0.48 m/s, a ball forward as fast). Call it after the impulses are stored in the
    // manifolds (wide solver) or while they are still in s.constraints (scalar solvers).
    void apply(Simulation& s) const;

private:
    // A contact the pass may visit: the world's contact and (scalar solvers) its constraint,
    // its restitution, its sides' BodyState indices (-1: static or asleep).
    struct Candidate {
        int contact = -1;
        int constraint = -1;
        float restitution = 0.0f;
        int indexA = -1;
        int indexB = -1;
    };
    // A contact of a row: its candidate, its sides (indices in bodies_; -1: a side no impulse
    // moves, its point's velocity in fixedA/fixedB), the normal and lever arms at the middle
    // of its points, 1 / effective mass, restitution, whether it is struck (approaching faster
    // than the threshold and closing within the step) and whether it is in order_ yet.
    struct Edge {
        int candidate = -1;
        int bodyA = -1;
        int bodyB = -1;
        Vec2 fixedA{0.0f, 0.0f};
        Vec2 fixedB{0.0f, 0.0f};
        Vec2 normal{0.0f, 0.0f};
        Vec2 rA{0.0f, 0.0f};
        Vec2 rB{0.0f, 0.0f};
        float invK = 0.0f;
        float restitution = 0.0f;
        bool struck = false;
        bool visited = false;
    };
    // A body of a row: its BodyState, mass properties and velocity (the step's starting one,
    // then the impacts' result).
    struct RowBody {
        int state = -1;
        Vec2 invMass{0.0f, 0.0f};
        float invInertia = 0.0f;
        Vec2 linearVelocity{0.0f, 0.0f};
        float angularVelocity = 0.0f;
        // At a root of rowParent_, how many contacts between two moving bodies its set has.
        int pairs = 0;
        bool reached = false; // in a treated row: apply() writes it
    };

    bool planCandidates(const Simulation& s, float dt);
    int localBody(int state, const Simulation& s);
    // Kinetic energy of a row body at the given velocities, J (a fixed axis counts nothing).
    static double kineticEnergy(const RowBody& b, Vec2 v, float w);
    bool sweep();

    std::vector<Candidate> candidates_;
    std::vector<Edge> edges_;
    std::vector<RowBody> bodies_;
    // Union-find over bodies_ by the contacts between two moving bodies (detail::findRoot).
    std::vector<int> rowParent_;
    std::vector<int> localOf_; // per BodyState: its index in bodies_, or -1
    std::vector<int> order_;   // the row contacts in the order the impulse travels
    // Each body's contacts: bodyEdges_[edgeStart_[b] .. edgeStart_[b + 1]), filled through
    // fill_.
    std::vector<int> edgeStart_;
    std::vector<int> bodyEdges_;
    std::vector<int> fill_;
    float threshold_ = 0.0f; // the restitution threshold, m/s
};

} // namespace e2d::physics::detail
