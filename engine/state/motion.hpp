// What one explicit cycle moves the nodes by (the damping) and what the last cycle of a batch
// measured: shared by the rock's nodes (solver/cycle.cpp) and the bolts' (bolt/bolt_coupling.cpp).
#pragma once

namespace edem {

// Velocity update coefficients of one cycle (the damping), for the rock's nodes and the bolts'.
struct Motion {
  double dt = 1.0;
  bool local = false;   // local damping
  double alpha = 0.0;   // its coefficient
  double keep = 1.0;    // viscous: v' = keep v + push F / m
  double push = 1.0;
  bool damped = false;  // takes energy out (local, or viscous with keep < 1)
};

// What the last cycle of a batch measured.
struct Measure {
  double unbalanced = 0.0;   // sum of |F| over free components [N/m]
  double applied = 0.0;      // sum of |zone corner forces| + |weight| + |load| [N/m]
  double kinetic = 0.0;      // 1/2 sum m v^2 with the cycling masses [J/m]
  double rayleigh_num = 0.0; // sum du . (r_start - r)
  double rayleigh_den = 0.0; // sum m du^2
  int inverted_zone = -1;    // lowest mesh zone turned inside out, or -1
  int fastest_node = -1;     // node with the largest speed
  int overlapping = -1;      // lowest contact with its gridpoint in the block past the limit, or -1
  double overlap = 0.0;      // how deep it is in the block (depth_in_block) [m]
  bool finite = true;        // every force and velocity finite
  // What the batch cost its team of threads: wall time, and the time its threads spent waiting
  // for each other at barriers, summed over the threads [s].
  int team = 1;
  double wall = 0.0;
  double waited = 0.0;
};

}  // namespace edem
