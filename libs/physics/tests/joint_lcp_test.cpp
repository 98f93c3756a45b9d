// SPDX-License-Identifier: MIT
// solveDenseLcp(): the joint limits' complementarity problem. For a positive definite A the
// solution is unique, so every answer is checked against the one found by trying every set of
// free rows.
#include "../src/joint_lcp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace e2d::physics::test {
namespace {

using detail::DenseLcpScratch;
using detail::solveDenseLcp;

// A = B B^T + shift I, m x m, row major.
std::vector<double> randomSpd(int m, std::mt19937& rng, double shift) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> b(static_cast<std::size_t>(m * m));
    for (double& v : b) {
        v = u(rng);
    }
    std::vector<double> a(static_cast<std::size_t>(m * m), 0.0);
    for (int i = 0; i < m; ++i) {
        for (int k = 0; k < m; ++k) {
            double sum = i == k ? shift : 0.0;
            for (int r = 0; r < m; ++r) {
                sum +=
                    b[static_cast<std::size_t>(i * m + r)] * b[static_cast<std::size_t>(k * m + r)];
            }
            a[static_cast<std::size_t>(i * m + k)] = sum;
        }
    }
    return a;
}

// The solution by enumeration: the free set whose x >= 0 and w >= 0 (Gaussian elimination).
std::vector<double> bruteForce(int m, const std::vector<double>& a, const std::vector<double>& q) {
    for (std::uint32_t mask = 0; mask < (1u << m); ++mask) {
        std::vector<int> f;
        for (int i = 0; i < m; ++i) {
            if ((mask >> i) & 1u) {
                f.push_back(i);
            }
        }
        const std::size_t k = f.size();
        std::vector<double> g(k * (k + 1));
        for (std::size_t r = 0; r < k; ++r) {
            for (std::size_t c = 0; c < k; ++c) {
                g[r * (k + 1) + c] = a[static_cast<std::size_t>(f[r] * m + f[c])];
            }
            g[r * (k + 1) + k] = -q[static_cast<std::size_t>(f[r])];
        }
        for (std::size_t c = 0; c < k; ++c) {
            for (std::size_t r = c + 1; r < k; ++r) {
                const double factor = g[r * (k + 1) + c] / g[c * (k + 1) + c];
                for (std::size_t e = c; e <= k; ++e) {
                    g[r * (k + 1) + e] -= factor * g[c * (k + 1) + e];
                }
            }
        }
        std::vector<double> x(static_cast<std::size_t>(m), 0.0);
        for (std::size_t r = k; r-- > 0;) {
            double v = g[r * (k + 1) + k];
            for (std::size_t c = r + 1; c < k; ++c) {
                v -= g[r * (k + 1) + c] * x[static_cast<std::size_t>(f[c])];
            }
            x[static_cast<std::size_t>(f[r])] = v / g[r * (k + 1) + r];
        }
        bool feasible = true;
        for (int i = 0; i < m && feasible; ++i) {
            double w = q[static_cast<std::size_t>(i)];
            for (int c = 0; c < m; ++c) {
                w += a[static_cast<std::size_t>(i * m + c)] * x[static_cast<std::size_t>(c)];
            }
            feasible =
                x[static_cast<std::size_t>(i)] >= -1e-9 && (((mask >> i) & 1u) || w >= -1e-9);
        }
        if (feasible) {
            return x;
        }
    }
    return {};
}

// Random positive definite problems of up to 7 rows, started from random guesses (a warm
// start that is wrong in both directions: rows to release and rows to take back): the unique
// solution every time.
TEST(JointLcp, MatchesEnumerationOnRandomProblems) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    DenseLcpScratch scratch;
    for (int trial = 0; trial < 300; ++trial) {
        const int m = 1 + trial % 7;
        const std::vector<double> a = randomSpd(m, rng, trial % 3 == 0 ? 1e-3 : 0.5);
        std::vector<double> q(static_cast<std::size_t>(m));
        std::vector<double> x(static_cast<std::size_t>(m));
        for (int i = 0; i < m; ++i) {
            q[static_cast<std::size_t>(i)] = u(rng);
            x[static_cast<std::size_t>(i)] = u(rng);
        }
        const std::vector<double> expected = bruteForce(m, a, q);
        ASSERT_EQ(expected.size(), static_cast<std::size_t>(m)) << trial;
        EXPECT_TRUE(solveDenseLcp(m, a, q, x, 4 * m + 8, scratch)) << trial;
        for (int i = 0; i < m; ++i) {
            EXPECT_NEAR(x[static_cast<std::size_t>(i)], expected[static_cast<std::size_t>(i)],
                        1e-6 * (1.0 + std::abs(expected[static_cast<std::size_t>(i)])))
                << "trial " << trial << " row " << i;
        }
    }
}

// A chain of stops like a limited arm's: A = B B^T, B bidiagonal with its scale falling a
// thousandfold from one end to the other (condition number above 10^6), most rows pushed,
// every fifth pulled. Complementary to round-off, from a cold start and from a warm start
// with every row free.
TEST(JointLcp, IllConditionedChainOfStops) {
    constexpr int m = 20;
    std::vector<double> b(static_cast<std::size_t>(m * m), 0.0);
    for (int i = 0; i < m; ++i) {
        const double scale = std::pow(1000.0, -static_cast<double>(i) / (m - 1));
        b[static_cast<std::size_t>(i * m + i)] = scale;
        if (i + 1 < m) {
            b[static_cast<std::size_t>((i + 1) * m + i)] = -scale;
        }
    }
    std::vector<double> a(static_cast<std::size_t>(m * m), 0.0);
    std::vector<double> q(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) {
        for (int k = 0; k < m; ++k) {
            for (int r = 0; r < m; ++r) {
                a[static_cast<std::size_t>(i * m + k)] +=
                    b[static_cast<std::size_t>(i * m + r)] * b[static_cast<std::size_t>(k * m + r)];
            }
        }
        q[static_cast<std::size_t>(i)] = i % 5 == 4 ? 0.5 : -1.0;
    }
    DenseLcpScratch scratch;
    for (double start : {0.0, 1.0}) {
        std::vector<double> x(static_cast<std::size_t>(m), start);
        ASSERT_TRUE(solveDenseLcp(m, a, q, x, 4 * m + 8, scratch));
        for (int i = 0; i < m; ++i) {
            // w to the round-off of its terms.
            double w = q[static_cast<std::size_t>(i)];
            double magnitude = std::abs(w);
            for (int c = 0; c < m; ++c) {
                const double term =
                    a[static_cast<std::size_t>(i * m + c)] * x[static_cast<std::size_t>(c)];
                w += term;
                magnitude += std::abs(term);
            }
            const double roundOff = 1e-9 * magnitude;
            EXPECT_GE(x[static_cast<std::size_t>(i)], 0.0) << i;
            EXPECT_GE(w, -roundOff) << i;
            if (x[static_cast<std::size_t>(i)] > 0.0) {
                EXPECT_NEAR(w, 0.0, roundOff) << i;
            }
        }
    }
}

} // namespace
} // namespace e2d::physics::test
