// Meshes and mechanics set up by hand for solver unit tests and benchmarks: structured
// squares whose answers are known, independent of the zoning.
#pragma once

#include <cmath>
#include <vector>

#include "constitutive/material.hpp"
#include "geom/mesh.hpp"
#include "solver/prepare.hpp"
#include "state/mechanics.hpp"

namespace edem::scenes {

// A square [0, side]^2 of n x n cells, each cut into two counter-clockwise triangles along
// its rising diagonal; one block whose outer loop is the model boundary.
inline Mesh square_mesh(int n, double side) {
  Mesh mesh;
  const double h = side / n;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      mesh.gp_position.push_back({i * h, j * h});
      mesh.gp_block.push_back(0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.zone_gp.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.zone_gp.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      mesh.zone_block.push_back(0);
      mesh.zone_block.push_back(0);
    }
  BoundaryLoop loop;
  for (int i = 0; i < n; ++i) loop.gridpoints.push_back(id(i, 0));
  for (int j = 0; j < n; ++j) loop.gridpoints.push_back(id(n, j));
  for (int i = n; i > 0; --i) loop.gridpoints.push_back(id(i, n));
  for (int j = n; j > 0; --j) loop.gridpoints.push_back(id(0, j));
  loop.edges.assign(loop.gridpoints.size(), EdgeOrigin{});
  mesh.block_boundary = {{loop}};
  mesh.block_first_gp = {0, mesh.gp_count()};
  mesh.block_first_zone = {0, mesh.zone_count()};
  return mesh;
}

// Mechanics for `mesh` with every zone of one material.
inline Mechanics mechanics_for(const Mesh& mesh, const MaterialDef& def) {
  Mechanics m;
  m.materials = {with_strength_defaults(def)};
  m.params = {material_params(def)};
  reset_for_mesh(m, mesh);
  m.zone_material.assign(static_cast<size_t>(mesh.zone_count()), 0);
  return m;
}

inline MaterialDef rock(double young = 10e9, double poisson = 0.25, double density = 2650) {
  MaterialDef def;
  def.name = "rock";
  def.young = young;
  def.poisson = poisson;
  def.density = density;
  return def;
}

}  // namespace edem::scenes
