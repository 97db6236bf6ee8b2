// A zone material is checked in one place, material_params(): material{} passes its messages on.
#include <gtest/gtest.h>

#include <string>

#include "constitutive/material.hpp"
#include "error_of.hpp"

namespace edem {
namespace {

MaterialDef elastic_rock() {
  MaterialDef def;
  def.name = "rock";
  def.young = 10e9;
  def.poisson = 0.25;
  return def;
}

// The message material_params rejects `def` with; empty when it accepts it.
std::string rejection(const MaterialDef& def) { return error_of([&] { material_params(def); }); }

TEST(Material, StrengthBelongsToTheMohrModel) {
  MaterialDef def = elastic_rock();
  def.cohesion = 1e6;
  def.tension = 1e5;
  EXPECT_EQ(rejection(def), "cohesion, tension need model = \"mohr\" or \"ss\" (this material's model is \"elastic\")");
  def.model = MaterialModel::mohr;
  EXPECT_EQ(rejection(def), "");
}

TEST(Material, UnsetStrengthsReadZero) {
  MaterialDef def = elastic_rock();
  def.model = MaterialModel::mohr;
  def.cohesion = 2e6;
  def.friction = 30;
  const MaterialParams p = material_params(def);
  EXPECT_EQ(p.tension, 0.0);
  EXPECT_EQ(p.npsi, 1.0);  // no dilation
  const MaterialDef kept = with_strength_defaults(def);
  EXPECT_EQ(kept.dilation, 0.0);
  EXPECT_EQ(kept.tension, 0.0);
  EXPECT_EQ(kept.cohesion, 2e6);
}

TEST(Material, ElasticConstantsComeInOnePairBothOfIt) {
  MaterialDef def = elastic_rock();
  def.bulk = 5e9;
  EXPECT_EQ(rejection(def), "give young and poisson, or bulk and shear, not both pairs");
  def = elastic_rock();
  def.poisson = kUnset;
  EXPECT_EQ(rejection(def), "young needs poisson too (or give bulk and shear)");
  def.young = kUnset;
  EXPECT_EQ(rejection(def), "missing elastic constants: give young and poisson, or bulk and shear");
  def.model = MaterialModel::null;
  EXPECT_EQ(rejection(def), "");
}

TEST(Material, DilationAtMostFriction) {
  MaterialDef def = elastic_rock();
  def.model = MaterialModel::mohr;
  def.friction = 30;
  def.dilation = 35;
  EXPECT_EQ(rejection(def), "dilation must be <= friction (30), got 35");
}

}  // namespace
}  // namespace edem
