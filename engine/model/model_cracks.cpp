// The Model's potential-crack commands and views: judge{}, sections, cracks.
#include <cmath>

#include "core/error.hpp"
#include "crack/judge.hpp"
#include "model/model.hpp"
#include "model/zone_in_rock.hpp"
#include "state/mechanics.hpp"
#include "solver/prepare.hpp"

namespace edem {

void Model::judge(const JudgeDef& def) {
  if (!(def.every >= 1)) fail("every must be >= 1, got {}", def.every);
  if (!(def.radius >= 0.0) || !std::isfinite(def.radius))
    fail("radius must be >= 0 (m), got {}", def.radius);
  // Another radius means other zones for every section's fit: prepare() fits them again.
  if (def.radius != mechanics_->judge.radius) mechanics_->dirty = true;
  mechanics_->judge = def;
  mechanics_->judge_criterion_missing = false;
}

int Model::section_count() const { return static_cast<int>(mechanics_->sections.size()); }

namespace {

// Whether the rock on both sides of section `s` is gone: its blocks have no zone of rock left,
// each dug or mucked out.
bool section_gone(const Mechanics& m, const Mesh& mesh, const Section& s) {
  if (m.zone_excavated.size() != static_cast<size_t>(mesh.zone_count())) return false;  // not zoned as laid
  for (const int block : s.block) {
    if (block < 0) continue;
    const size_t b = static_cast<size_t>(block);
    for (int z = mesh.block_first_zone[b]; z < mesh.block_first_zone[b + 1]; ++z)
      if (zone_in_rock(m, static_cast<size_t>(z))) return false;
  }
  return true;
}

}  // namespace

SectionView Model::section(int id) const {
  Mechanics& m = *mechanics_;
  if (id < 0 || id >= section_count()) fail("no section {}: the model has {}", id + 1, section_count());
  prepare(m, mesh_);  // the fits
  SectionView v = section_view(m, id);
  v.gone = section_gone(m, mesh_, m.sections[static_cast<size_t>(id)]);
  if (v.gone) v.overstress = 0.0;  // no rock: nothing to judge
  return v;
}

int Model::crack_count() const { return static_cast<int>(mechanics_->cracks.size()); }

const CrackView& Model::crack(int id) const {
  if (id < 0 || id >= crack_count()) fail("no crack {}: the model has {}", id + 1, crack_count());
  return mechanics_->cracks[static_cast<size_t>(id)];
}

void Model::add_crack_counts(ModelInfo& info) const {
  const Mechanics& m = *mechanics_;
  info.sections = static_cast<int>(m.sections.size());
  info.cracks = static_cast<int>(m.cracks.size());
  info.intact_sections = 0;
  for (const Section& s : m.sections)
    if (s.mode == CrackMode::none && !section_gone(m, mesh_, s)) ++info.intact_sections;
  for (const CrackView& c : m.cracks) {
    if (c.mode == CrackMode::shear) ++info.shear_cracks;
    if (c.mode == CrackMode::tension) ++info.tension_cracks;
  }
}

}  // namespace edem
