// SPDX-License-Identifier: MIT
// The joint limits' complementarity problem: a few tens of rows, so a dense factorisation per
// pivoting round is cheap, and the answer is exact (an active set that only releases limits,
// or projected Gauss-Seidel on an ill-conditioned A, is not).
#include "joint_lcp.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace e2d::physics::detail {

namespace {

// A pivot below this fraction of its row's own diagonal is a row that depends on the earlier
// ones (round-off of an exactly singular A): it is held at 0.
constexpr double kCollapsedPivot = 1e-12;

// x_F = -A_FF^-1 q_F for the free rows F, x = 0 elsewhere (LDL^T, no pivoting: A_FF is
// positive semi-definite).
void solveFree(int m, std::span<const double> a, std::span<const double> q, std::span<double> x,
               DenseLcpScratch& s) {
    s.index.clear();
    for (int i = 0; i < m; ++i) {
        x[static_cast<std::size_t>(i)] = 0.0;
        if (s.free[static_cast<std::size_t>(i)] != 0) {
            s.index.push_back(i);
        }
    }
    const std::size_t k = s.index.size();
    s.factor.assign(k * k, 0.0);
    s.pivot.assign(k, 0.0);
    auto at = [&](std::size_t r, std::size_t c) -> double& { return s.factor[r * k + c]; };
    auto aOf = [&](std::size_t r, std::size_t c) {
        return a[static_cast<std::size_t>(s.index[r]) * static_cast<std::size_t>(m) +
                 static_cast<std::size_t>(s.index[c])];
    };
    // Plain LDL^T, L unit lower, stored below the diagonal; D on it.
    for (std::size_t j = 0; j < k; ++j) {
        double d = aOf(j, j);
        for (std::size_t p = 0; p < j; ++p) {
            d -= at(j, p) * at(j, p) * at(p, p);
        }
        const bool collapsed = !(d > kCollapsedPivot * std::abs(aOf(j, j)));
        at(j, j) = collapsed ? 0.0 : d;
        s.pivot[j] = collapsed ? 0.0 : 1.0 / d;
        for (std::size_t r = j + 1; r < k; ++r) {
            double v = aOf(r, j);
            for (std::size_t p = 0; p < j; ++p) {
                v -= at(r, p) * at(j, p) * at(p, p);
            }
            at(r, j) = v * s.pivot[j];
        }
    }
    // L y = -q_F, then D z = y, then L^T x = z.
    std::vector<double>& y = s.w; // reused; w is recomputed after
    y.assign(k, 0.0);
    for (std::size_t r = 0; r < k; ++r) {
        double v = -q[static_cast<std::size_t>(s.index[r])];
        for (std::size_t p = 0; p < r; ++p) {
            v -= at(r, p) * y[p];
        }
        y[r] = v;
    }
    for (std::size_t r = 0; r < k; ++r) {
        y[r] *= s.pivot[r];
    }
    for (std::size_t r = k; r-- > 0;) {
        double v = y[r];
        for (std::size_t p = r + 1; p < k; ++p) {
            v -= at(p, r) * y[p];
        }
        y[r] = v;
    }
    s.dependent.assign(static_cast<std::size_t>(m), 0);
    for (std::size_t r = 0; r < k; ++r) {
        const auto i = static_cast<std::size_t>(s.index[r]);
        x[i] = s.pivot[r] != 0.0 ? y[r] : 0.0;
        s.dependent[i] = s.pivot[r] != 0.0 ? 0 : 1;
    }
}

} // namespace

bool solveDenseLcp(int m, std::span<const double> a, std::span<const double> q, std::span<double> x,
                   int maxRounds, DenseLcpScratch& s) {
    const auto n = static_cast<std::size_t>(m);
    s.free.resize(n);
    double scaleQ = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        s.free[i] = x[i] > 0.0 ? 1 : 0;
        scaleQ = std::max(scaleQ, std::abs(q[i]));
    }
    // Round-off: a free row a hair below 0, or a held one a hair below 0 in w, is feasible.
    const double tolW = 1e-10 * scaleQ;
    int best = m + 1;
    int allowance = 3; // rounds flipping every infeasible row without progress
    bool solved = false;
    for (int round = 0; round < maxRounds && !solved; ++round) {
        solveFree(m, a, q, x, s);
        double scaleX = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            scaleX = std::max(scaleX, std::abs(x[i]));
        }
        const double tolX = 1e-10 * scaleX;
        s.w.assign(n, 0.0);
        int infeasible = 0;
        int highest = -1;
        for (std::size_t i = 0; i < n; ++i) {
            bool bad = false;
            if (s.free[i] != 0 && s.dependent[i] == 0) {
                bad = x[i] < -tolX;
            } else { // held at 0 (a dependent row too): its w must not be negative
                double wi = q[i];
                for (std::size_t k = 0; k < n; ++k) {
                    wi += a[i * n + k] * x[k];
                }
                s.w[i] = wi;
                bad = wi < -tolW;
            }
            if (bad) {
                ++infeasible;
                highest = static_cast<int>(i);
                s.w[i] = -1.0; // marks the row for the flip below
            } else {
                s.w[i] = 0.0;
            }
        }
        if (infeasible == 0) {
            solved = true;
            break;
        }
        bool all = false;
        if (infeasible < best) {
            best = infeasible;
            allowance = 3;
            all = true;
        } else if (allowance > 0) {
            --allowance;
            all = true;
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (s.w[i] < 0.0 && (all || static_cast<int>(i) == highest)) {
                s.free[i] = s.free[i] != 0 ? 0 : 1;
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = std::max(x[i], 0.0);
    }
    return solved;
}

} // namespace e2d::physics::detail
