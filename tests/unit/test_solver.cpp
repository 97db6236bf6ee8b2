// The explicit solver on hand-made meshes: patch test, 1-DOF period and stability limit, the
// automatic step against the exact critical step, the watchdog, thread independence.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "constitutive/mohr_coulomb.hpp"
#include "core/error.hpp"
#include "solver/cycle.hpp"
#include "solver/run.hpp"
#include "solver/zone_groups.hpp"
#include "solver_scenes.hpp"

namespace edem {
namespace {

using scenes::mechanics_for;
using scenes::rock;
using scenes::square_mesh;

// A square mesh with its interior gridpoints moved at random (but keeping zones valid).
Mesh jittered_square(int n, double side, unsigned seed) {
  Mesh mesh = square_mesh(n, side);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  const double h = side / n;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) {
      Vec2& p = mesh.gp_position[static_cast<size_t>(j * (n + 1) + i)];
      p.x += jitter(random) * h;
      p.y += jitter(random) * h;
    }
  return mesh;
}

bool on_boundary(const Mechanics& m, int node, double side) {
  const double x = m.position[2 * static_cast<size_t>(node)];
  const double y = m.position[2 * static_cast<size_t>(node) + 1];
  return x == 0.0 || y == 0.0 || x == side || y == side;
}

// Imposed strain exx, eyy, gxy (engineering) -> stress, plane strain.
Stress hooke(const MaterialParams& p, double exx, double eyy, double gxy) {
  Stress s;
  elastic_update(p, s, exx, eyy, gxy);
  return s;
}

// Every node held on the linear velocity field u = (exx x + gxy y, eyy y) (engineering gxy).
void hold_linear_field(Mechanics& m, double exx, double eyy, double gxy) {
  for (int n = 0; n < m.node_count; ++n) {
    const size_t k = static_cast<size_t>(n);
    m.v[2 * k] = exx * m.position[2 * k] + gxy * m.position[2 * k + 1];
    m.v[2 * k + 1] = eyy * m.position[2 * k + 1];
    m.fix[k] = 3;  // held, so the field stays linear
  }
}

// After one step of a held linear field: every zone has the stress of that strain, and every
// interior node is balanced.
void expect_uniform_stress_and_balance(const Mechanics& m, double exx, double eyy, double gxy,
                                       double side, int cells) {
  const Stress expected = hooke(m.params[0], exx, eyy, gxy);
  const double scale = std::fabs(expected.yy);
  for (const Stress& s : m.stress) {
    EXPECT_LE(std::fabs(s.xx - expected.xx), 1e-12 * scale);
    EXPECT_LE(std::fabs(s.yy - expected.yy), 1e-12 * scale);
    EXPECT_LE(std::fabs(s.xy - expected.xy), 1e-12 * scale);
    EXPECT_LE(std::fabs(s.zz - expected.zz), 1e-12 * scale);
  }
  const double typical = scale * side / cells;  // stress x zone size [N/m]
  for (int n = 0; n < m.node_count; ++n)
    if (!on_boundary(m, n, side)) {
      EXPECT_LE(std::fabs(m.force[2 * static_cast<size_t>(n)]), 1e-10 * typical);
      EXPECT_LE(std::fabs(m.force[2 * static_cast<size_t>(n) + 1]), 1e-10 * typical);
    }
}

TEST(PatchTest, LinearVelocityFieldGivesUniformStressAndBalancedInteriorNodes) {
  const double side = 3.0, exx = 1e-4, eyy = -2e-4, gxy = 3e-4;
  const Mesh mesh = jittered_square(8, side, 7);
  Mechanics m = mechanics_for(mesh, rock());
  hold_linear_field(m, exx, eyy, gxy);
  prepare(m, mesh);
  run_cycles(m, 1);  // static mode: step 1
  expect_uniform_stress_and_balance(m, exx, eyy, gxy, side, 8);
}

TEST(PatchTest, BoundaryStrainRelaxesToUniformStress) {
  const double side = 2.0, exx = -1e-4, eyy = 0.5e-4, gxy = 2e-4;
  const Mesh mesh = jittered_square(10, side, 3);
  Mechanics m = mechanics_for(mesh, rock());
  for (int n = 0; n < m.node_count; ++n)
    if (on_boundary(m, n, side)) {
      const size_t k = static_cast<size_t>(n);
      m.v[2 * k] = exx * m.position[2 * k] + gxy * m.position[2 * k + 1];
      m.v[2 * k + 1] = eyy * m.position[2 * k + 1];
      m.fix[k] = 3;
    }
  run_solver(m, mesh, 1, 0.0);  // one step of 1 s puts the boundary in place
  for (size_t k = 0; k < m.fix.size(); ++k)
    if (m.fix[k]) m.v[2 * k] = m.v[2 * k + 1] = 0.0;
  m.dirty = true;
  const SolveResult result = run_solver(m, mesh, 20000, 1e-14);
  EXPECT_TRUE(result.converged) << "ratio " << result.ratio;
  const Stress expected = hooke(m.params[0], exx, eyy, gxy);
  const double scale = std::fabs(expected.xx);
  for (const Stress& s : m.stress) {
    EXPECT_LE(std::fabs(s.xx - expected.xx), 1e-10 * scale);
    EXPECT_LE(std::fabs(s.yy - expected.yy), 1e-10 * scale);
    EXPECT_LE(std::fabs(s.xy - expected.xy), 1e-10 * scale);
  }
}

TEST(PatchTest, MixedDiscretisationKeepsAUniformStrainUniform) {
  // The group average of a uniform volumetric strain rate is that rate: B-bar passes the patch test.
  const double side = 3.0, exx = 1e-4, eyy = -2e-4, gxy = 3e-4;
  const Mesh mesh = jittered_square(8, side, 11);
  Mechanics m = mechanics_for(mesh, rock());
  m.settings.mixed = true;
  hold_linear_field(m, exx, eyy, gxy);
  prepare(m, mesh);
  ASSERT_FALSE(m.mates.empty());
  run_cycles(m, 1);
  expect_uniform_stress_and_balance(m, exx, eyy, gxy, side, 8);
}

TEST(ZoneGroups, NeighbouringPairsAndTriplesCoverNearlyEveryZone) {
  const Mesh mesh = jittered_square(30, 10.0, 5);  // 1800 zones
  Mechanics m = mechanics_for(mesh, rock());
  m.settings.mixed = true;
  prepare(m, mesh);
  const auto& mates = m.mates;
  ASSERT_EQ(mates.size(), m.active.size());
  auto shares_edge = [&](int a, int b) {
    int common = 0;
    for (int p : m.geometry[static_cast<size_t>(m.active[static_cast<size_t>(a)])].node)
      for (int q : m.geometry[static_cast<size_t>(m.active[static_cast<size_t>(b)])].node) common += p == q;
    return common == 2;
  };
  int alone = 0, triples = 0;
  for (int k = 0; k < static_cast<int>(mates.size()); ++k) {
    const auto& o = mates[static_cast<size_t>(k)];
    if (o[0] < 0) {
      EXPECT_LT(o[1], 0);
      ++alone;
      continue;
    }
    triples += o[1] >= 0;
    for (int j = 0; j < 2; ++j) {
      const int other = o[static_cast<size_t>(j)];
      if (other < 0) continue;
      EXPECT_NE(other, k);
      // Membership is symmetric: the other member lists k.
      const auto& back = mates[static_cast<size_t>(other)];
      EXPECT_TRUE(back[0] == k || back[1] == k) << k << " " << other;
    }
    // Every member touches another member along an edge.
    EXPECT_TRUE(shares_edge(k, o[0]) || (o[1] >= 0 && shares_edge(k, o[1])));
  }
  std::printf("%zu zones: %d alone, %d in triples\n", mates.size(), alone, triples / 3);
  EXPECT_LE(alone, static_cast<int>(mates.size()) / 100);
  // The same input gives the same groups.
  EXPECT_EQ(group_zones(m.geometry, m.active, m.position), mates);
}

// One triangle whose third corner moves in y only: a mass on a spring.
struct OneDof {
  Mesh mesh;
  Mechanics m;
  double omega = 0.0;  // exact angular frequency [1/s]
};

OneDof one_dof() {
  OneDof s;
  s.mesh.gp_position = {{0, 0}, {1, 0}, {0, 1}};
  s.mesh.gp_block = {0, 0, 0};
  s.mesh.zone_gp = {{0, 1, 2}};
  s.mesh.zone_block = {0};
  s.mesh.block_first_gp = {0, 3};
  s.mesh.block_first_zone = {0, 1};
  s.mesh.block_boundary = {{BoundaryLoop{{0, 1, 2}, {EdgeOrigin{}, EdgeOrigin{}, EdgeOrigin{}}}}};
  s.m = mechanics_for(s.mesh, rock(1e9, 0.25, 3000));
  s.m.settings.mode = SolverMode::dynamic;
  s.m.settings.damping = Damping::none;
  s.m.fix = {3, 3, 1};
  // Node 2 at (0, 1): dN/dx = 0, dN/dy = 1 over an area of 1/2, so k = e1 / 2; m = rho A / 3.
  const double k = 0.5 * s.m.params[0].e1, mass = 3000.0 * 0.5 / 3.0;
  s.omega = std::sqrt(k / mass);
  return s;
}

TEST(Dynamic, OneDofPeriodIsTheDiscreteLeapfrogPeriod) {
  OneDof s = one_dof();
  const double step = 0.2 / s.omega;
  s.m.settings.step = step;
  s.m.v[5] = 1.0;
  prepare(s.m, s.mesh);
  ASSERT_EQ(s.m.step, step);
  // Zero crossings of u over ~100 periods, linearly interpolated.
  std::vector<double> crossings;
  double previous = s.m.u[5];
  for (int i = 1; i <= 3200; ++i) {
    run_cycles(s.m, 1);
    const double now = s.m.u[5];
    if (previous > 0.0 && now <= 0.0) crossings.push_back((i - 1 + previous / (previous - now)) * step);
    previous = now;
  }
  ASSERT_GE(crossings.size(), 90u);
  const double measured = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double discrete = 2.0 * std::numbers::pi / (std::acos(1.0 - 0.5 * 0.2 * 0.2) / step);
  EXPECT_NEAR(measured / discrete, 1.0, 1e-4);
  std::printf("1-DOF period: measured %.9g s, discrete %.9g s, exact %.9g s, error %.2e\n",
              measured, discrete, 2 * std::numbers::pi / s.omega, measured / discrete - 1.0);
}

TEST(Dynamic, AboveTheCriticalStepGrowsAsPredictedAndTheWatchdogStopsIt) {
  OneDof s = one_dof();
  const double critical = 2.0 / s.omega;
  s.m.settings.step = 1.05 * critical;
  s.m.v[5] = 1.0;
  prepare(s.m, s.mesh);
  EXPECT_NEAR(s.m.critical_step, critical, 1e-12 * critical);  // exact for one DOF
  // |lambda| of lambda^2 - (2 - w^2 dt^2) lambda + 1 = 0 at w dt = 2.1
  const double b = 2.0 - 2.1 * 2.1;
  const double lambda = std::fabs((b - std::sqrt(b * b - 4.0)) / 2.0);
  double previous = 0.0, ratio = 0.0;
  for (int i = 0; i < 40; ++i) {
    run_cycles(s.m, 1);
    if (previous != 0.0) ratio = std::fabs(s.m.u[5] / previous);
    previous = s.m.u[5];
  }
  EXPECT_NEAR(ratio / lambda, 1.0, 0.01) << "growth per step " << ratio << ", predicted " << lambda;
  OneDof again = one_dof();
  again.m.settings.step = 1.05 * critical;
  again.m.v[5] = 1.0;
  try {
    run_solver(again.m, again.mesh, 100000, 0.0);
    FAIL() << "the watchdog did not stop the run";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("unstable"), std::string::npos) << message;
    EXPECT_NE(message.find("forced time step"), std::string::npos) << message;
    EXPECT_NE(message.find("near (0, 1)"), std::string::npos) << message;
    EXPECT_LT(again.m.info.cycle, 200);
  }
  for (double value : again.m.u) EXPECT_TRUE(std::isfinite(value));
}

TEST(Dynamic, AutomaticStepIsBelowTheExactCriticalStep) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Mesh mesh = jittered_square(4, 1.0, seed);
    Mechanics m = mechanics_for(mesh, rock(20e9, 0.3, 2000));
    m.settings.mode = SolverMode::dynamic;
    m.settings.damping = Damping::none;
    prepare(m, mesh);
    // Dense K of the constant-strain triangles (the mixed form is never stiffer) and lumped M.
    const int dofs = 2 * m.node_count;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
    const MaterialParams& p = m.params[0];
    for (const ZoneGeometry& g : m.geometry) {
      Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
      for (int i = 0; i < 3; ++i) {
        B(0, 2 * i) = g.b[i];
        B(1, 2 * i + 1) = g.c[i];
        B(2, 2 * i) = g.c[i];
        B(2, 2 * i + 1) = g.b[i];
      }
      Eigen::Matrix3d D;
      D << p.e1, p.e2, 0, p.e2, p.e1, 0, 0, 0, p.shear;
      const Eigen::Matrix<double, 6, 6> k = g.area * B.transpose() * D * B;
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
          K(2 * g.node[static_cast<size_t>(i / 2)] + i % 2, 2 * g.node[static_cast<size_t>(j / 2)] + j % 2) += k(i, j);
    }
    Eigen::VectorXd inv_sqrt_mass(dofs);
    for (int d = 0; d < dofs; ++d) inv_sqrt_mass(d) = 1.0 / std::sqrt(m.mass[static_cast<size_t>(d / 2)]);
    const Eigen::MatrixXd A = inv_sqrt_mass.asDiagonal() * K * inv_sqrt_mass.asDiagonal();
    const double lambda_max = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff();
    const double critical = 2.0 / std::sqrt(lambda_max);
    EXPECT_LE(m.step, critical);
    EXPECT_GE(m.step, 0.3 * critical);  // not needlessly small
    std::printf("seed %u: automatic step %.4g s = %.3f of the exact critical step %.4g s\n", seed,
                m.step, m.step / critical, critical);
  }
}

TEST(Dynamic, FreeVibrationWithTheAutomaticStepConservesEnergy) {
  const Mesh mesh = jittered_square(6, 1.0, 5);
  Mechanics m = mechanics_for(mesh, rock(20e9, 0.3, 2000));
  m.settings.mode = SolverMode::dynamic;
  m.settings.damping = Damping::none;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  for (double& v : m.v) v = speed(random);
  const SolveResult result = run_solver(m, mesh, 20000, 0.0);
  EXPECT_EQ(result.cycles, 20000);
  for (double v : m.v) EXPECT_LT(std::fabs(v), 10.0);
}

void fill_gravity_model(Mechanics& m, bool mohr) {
  if (mohr) {
    MaterialDef def = rock();
    def.model = MaterialModel::mohr;
    def.cohesion = 2e5;
    def.friction = 30;
    def.tension = 1e5;
    m.materials = {def};
    m.params = {material_params(def)};
  }
  m.gravity = {0.0, -9.81};
  m.gravity_set = true;
  for (int n = 0; n < m.node_count; ++n)
    if (m.position[2 * static_cast<size_t>(n) + 1] == 0.0) m.fix[static_cast<size_t>(n)] = 3;
}

TEST(Threads, TwoThreadsGiveTheSameBitsAsOne) {
  const Mesh mesh = jittered_square(60, 30.0, 9);  // 7200 zones: several chunks per thread
  Mechanics one = mechanics_for(mesh, rock()), two = mechanics_for(mesh, rock());
  fill_gravity_model(one, true);
  fill_gravity_model(two, true);
  one.threads = 1;
  two.threads = 2;
  two.thread_watch.hold_down = 1e9;  // two threads however busy the machine is (ctest -j2)
  run_solver(one, mesh, 300, 0.0);
  run_solver(two, mesh, 300, 0.0);
  ASSERT_EQ(two.partition.threads, 2);
  EXPECT_GT(two.partition.gather.size(), 0u);  // some nodes are shared between the threads
  EXPECT_EQ(std::memcmp(one.u.data(), two.u.data(), one.u.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(one.v.data(), two.v.data(), one.v.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(one.stress.data(), two.stress.data(), one.stress.size() * sizeof(Stress)), 0);
  EXPECT_EQ(one.info.ratio, two.info.ratio);
  bool yielded = false;
  for (auto state : one.zone_state) yielded |= state != 0;
  EXPECT_TRUE(yielded) << "the test should exercise plasticity too";
}

TEST(Threads, MixedDiscretisationGivesTheSameBitsOnTwoThreads) {
  const Mesh mesh = jittered_square(60, 30.0, 13);  // groups straddle the threads' ranges
  Mechanics one = mechanics_for(mesh, rock()), two = mechanics_for(mesh, rock());
  for (Mechanics* m : {&one, &two}) {
    fill_gravity_model(*m, true);
    m->settings.mixed = true;
  }
  one.threads = 1;
  two.threads = 2;
  run_solver(one, mesh, 300, 0.0);
  run_solver(two, mesh, 300, 0.0);
  EXPECT_EQ(std::memcmp(one.u.data(), two.u.data(), one.u.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(one.stress.data(), two.stress.data(), one.stress.size() * sizeof(Stress)), 0);
  EXPECT_EQ(one.info.ratio, two.info.ratio);
}

TEST(Static, GravityColumnMatchesRhoGDepth) {
  // Roller sides, fixed base: syy = rho g (y - H), sxx = nu / (1 - nu) syy.
  const double side = 10.0, rho = 2650, g = 9.81, nu = 0.25;
  const Mesh mesh = square_mesh(10, side);
  Mechanics m = mechanics_for(mesh, rock(10e9, nu, rho));
  m.gravity = {0.0, -g};
  m.gravity_set = true;
  for (int n = 0; n < m.node_count; ++n) {
    const double x = m.position[2 * static_cast<size_t>(n)], y = m.position[2 * static_cast<size_t>(n) + 1];
    if (y == 0.0) m.fix[static_cast<size_t>(n)] = 3;
    if (x == 0.0 || x == side) m.fix[static_cast<size_t>(n)] |= 1;
  }
  const SolveResult result = run_solver(m, mesh, 50000, 1e-8);
  ASSERT_TRUE(result.converged);
  std::printf("column of 10 x 10 cells: %ld cycles to ratio 1e-8\n", result.cycles);
  // A zone's stress is nearly that of its row of cells at mid-height (the 1D answer), so the
  // zones of a cell average to rho g depth at the cell centre, and each zone is off by about
  // rho g h / 6 (h the cell height). Not exactly: the top corners carry different weights
  // (one triangle at the left, two at the right), which disturbs the field by ~0.25 % of rho g H
  // here; the check allows 0.5 %, as tests/verification/gravity_column.lua does.
  const double scale = rho * g * side, h = side / 10;
  for (size_t z = 0; z < m.stress.size(); z += 2) {
    const Vec2 c = 0.5 * (mesh.zone_centroid(static_cast<int>(z)) + mesh.zone_centroid(static_cast<int>(z) + 1));
    if (c.x < 0.3 * side || c.x > 0.7 * side) continue;  // away from the unequal corners
    const double syy = rho * g * (c.y - side);
    EXPECT_NEAR(0.5 * (m.stress[z].yy + m.stress[z + 1].yy), syy, 5e-3 * scale) << "cell " << z / 2;
    EXPECT_NEAR(0.5 * (m.stress[z].xx + m.stress[z + 1].xx), nu / (1 - nu) * syy, 5e-3 * scale);
    EXPECT_NEAR(m.stress[z].yy, syy, rho * g * h / 6 + 5e-3 * scale);
  }
  // Settlement of the top centre: rho g H^2 / (2 M), M the constrained modulus.
  const size_t top = 2 * static_cast<size_t>(10 * 11 + 5) + 1;
  ASSERT_EQ(m.position[top], side);
  EXPECT_NEAR(-m.u[top] / (rho * g * side * side / (2 * m.params[0].e1)), 1.0, 5e-3);
}

}  // namespace
}  // namespace edem
