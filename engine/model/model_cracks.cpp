// The Model's potential-crack commands and views: judge{}, sections, cracks.
#include <cmath>

#include "core/error.hpp"
#include "crack/judge.hpp"
#include "model/model.hpp"
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

SectionView Model::section(int id) const {
  Mechanics& m = *mechanics_;
  if (id < 0 || id >= section_count()) fail("no section {}: the model has {}", id + 1, section_count());
  prepare(m, mesh_);  // the fits
  return section_view(m, id);
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
  info.intact_sections = info.sections - info.cracks;
  for (const CrackView& c : m.cracks) {
    if (c.mode == CrackMode::shear) ++info.shear_cracks;
    if (c.mode == CrackMode::tension) ++info.tension_cracks;
  }
}

}  // namespace edem
