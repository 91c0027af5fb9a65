#include "bsdfs/per_point_parameters.h"

namespace columba {

PerPointParameterSources::PerPointParameterSources(const Properties& props, const std::string& preset,
                                                   std::initializer_list<Parameter> parameters)
    : plugin_(props.type) {
  const bool presetGiven = !preset.empty() && props.has(preset);
  if (presetGiven) preset_ = props.getString(preset);
  for (const Parameter& p : parameters) {
    if (p.textured) continue;
    if (props.has(p.name))
      sources_.push_back({p.name, p.key, props.locationOf(p.name), false});
    else if (presetGiven)
      sources_.push_back({p.name, p.key, props.locationOf(preset), true});
  }
}

void PerPointParameterSources::warnIfShadowed(const SurfaceAttributeSet& everywhere, const std::string& shape) const {
  // One warning per line: a preset's parameters share its line.
  std::vector<bool> done(sources_.size());
  for (size_t i = 0; i < sources_.size(); ++i) {
    if (done[i] || !everywhere.contains(sources_[i].key)) continue;
    std::string names;
    int count = 0;
    uint32_t bits = 0;
    for (size_t j = i; j < sources_.size(); ++j)
      if (!done[j] && everywhere.contains(sources_[j].key) && sources_[j].where.line == sources_[i].where.line &&
          sources_[j].where.file == sources_[i].where.file) {
        done[j] = true;
        bits |= uint32_t(1) << j;
        names += (count++ ? ", '" : "'") + sources_[j].name + "'";
      }
    if (warned_.fetch_or(bits) & bits) continue;  // already said for an earlier shape
    const std::string given = sources_[i].fromPreset ? " (from preset '" + preset_ + "')" : "";
    warn(sources_[i].where, plugin_ + ", " + (count > 1 ? "parameters " : "parameter ") + names + given +
                                ": no effect on " + shape + ", whose own per-point values win; a texture for " +
                                (count > 1 ? "each" : "it") +
                                " takes effect there (docs/feather-ply.md, \"Which value wins\")");
  }
}

}  // namespace columba
