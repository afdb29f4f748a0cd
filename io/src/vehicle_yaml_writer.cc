// Writes a vehicle file (contract §Vehicle) that ReadVehicle reads back to the vehicle it
// printed: the virtual pool stores the truth's vehicle beside the campaign it simulates;
// `identify` and `diagnose --write-vehicle` add the identified model. Numbers as people read
// them (number_text.h): the shortest exact text of at most 10 digits, estimates rounded from
// their σ.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "speed_limit_keys.h"
#include "thruster_installation_yaml.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/number_text.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/parameter.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the vehicle file

namespace {

using Key = std::pair<const char*, double>;

// {k1: v1, k2: v2, ...} on one line.
void EmitFlowMap(YAML::Emitter& out, std::initializer_list<Key> items) {
  out << YAML::Flow << YAML::BeginMap;
  for (const auto& [key, value] : items) {
    out << YAML::Key << key << YAML::Value << FileNumber(value);
  }
  out << YAML::EndMap;
}

void EmitPair(YAML::Emitter& out, const std::array<double, 2>& p) {
  out << YAML::Flow << YAML::BeginSeq << FileNumber(p[0]) << FileNumber(p[1]) << YAML::EndSeq;
}

// {name: σ, ...}, each σ to 2 significant digits.
void EmitSigmas(YAML::Emitter& out, const std::map<std::string, double>& sigmas) {
  out << YAML::BeginMap;
  for (const auto& [key, sigma] : sigmas)
    out << YAML::Key << key << YAML::Value << SigmaNumber(sigma);
  out << YAML::EndMap;
}

void EmitSensor(YAML::Emitter& out, const char* key, const std::optional<SensorSpec>& s) {
  if (!s) return;
  out << YAML::Key << key << YAML::Value;
  EmitFlowMap(out, {{"rate", s->rate_hz}, {"sigma", s->sigma}});
}

// `key: {<dof>: {...}}` with the block of each DOF written by `emit`; nothing when empty.
template <typename PerDof, typename Emit>
void EmitPerDof(YAML::Emitter& out, const char* key, const PerDof& per_dof, Emit emit) {
  if (per_dof.empty()) return;
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  for (const auto& [dof, item] : per_dof) {
    out << YAML::Key << std::string(DofName(dof)) << YAML::Value << YAML::BeginMap;
    emit(item);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

void EmitThruster(YAML::Emitter& out, const Thruster& t) {
  out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << t.name;
  out << YAML::Key << "thrust" << YAML::Value << YAML::BeginMap;
  if (t.model.kind == ThrustModel::Kind::kSquare) {
    out << YAML::Key << "model" << YAML::Value << "square" << YAML::Key << "c_pos" << YAML::Value
        << FileNumber(t.model.c_pos) << YAML::Key << "c_neg" << YAML::Value
        << FileNumber(t.model.c_neg);
  } else {
    out << YAML::Key << "model" << YAML::Value << "poly2" << YAML::Key << "a" << YAML::Value
        << FileNumber(t.model.a) << YAML::Key << "b" << YAML::Value << FileNumber(t.model.b);
  }
  if (t.model.deduction != 0.0) {
    out << YAML::Key << "deduction" << YAML::Value << FileNumber(t.model.deduction);
  }
  if (t.model.dead_band != 0.0) {
    out << YAML::Key << "dead_band" << YAML::Value << FileNumber(t.model.dead_band);
  }
  out << YAML::EndMap << YAML::Key << "command" << YAML::Value;
  EmitPair(out, {t.command_min, t.command_max});
  if (t.neutral != 0.0) out << YAML::Key << "neutral" << YAML::Value << FileNumber(t.neutral);
  EmitThrusterInstallation(out, t);
  out << YAML::EndMap;
}

void EmitMappings(YAML::Emitter& out, const Vehicle& v) {
  out << YAML::Key << "mappings" << YAML::Value << YAML::BeginMap;
  for (const auto& m : v.mappings) {
    out << YAML::Key << m.name << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "dof" << YAML::Value << std::string(DofName(m.dof));
    out << YAML::Key << "shares" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [index, share] : m.shares) {
      out << YAML::Key << v.thrusters.at(index).name << YAML::Value << FileNumber(share);
    }
    out << YAML::EndMap;
    out << YAML::Key << "open_water" << YAML::Value << std::string(OpenWaterName(m.open_water));
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

void EmitBody(YAML::Emitter& out, const Vehicle& v) {
  out << YAML::Key << "name" << YAML::Value << v.name;
  out << YAML::Key << "mass" << YAML::Value << FileNumber(v.mass);
  out << YAML::Key << "size" << YAML::Value << YAML::Flow << YAML::BeginSeq << FileNumber(v.size[0])
      << FileNumber(v.size[1]) << FileNumber(v.size[2]) << YAML::EndSeq;
  if (!v.inertia.empty()) {
    out << YAML::Key << "inertia" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [dof, value] : v.inertia) {
      out << YAML::Key << std::string(DofName(dof)) << YAML::Value << FileNumber(value);
    }
    out << YAML::EndMap;
  }
  out << YAML::Key << "added_mass" << YAML::Value;
  EmitPair(out, v.added_mass);
}

// A parameter's value as the file gives it: an estimate rounded from its σ, else exact.
std::string ParameterNumber(const DofParameters& model, const std::string& name, double value) {
  const auto sigma = model.sigma.find(name);
  return sigma == model.sigma.end() ? FileNumber(value) : EstimateNumber(value, sigma->second);
}

// {m, k, kq, bias, bias_step, eta: {<mapping>.<dir>: v}} and {<effect>: {<key>: v, ...}} of a
// model (truth_yaml.cc and truth_effects.cc read them back): each parameter where its family
// puts it in a truth file.
void EmitModel(YAML::Emitter& out, const DofParameters& model) {
  using Texts = std::map<std::string, std::string>;
  Texts eta;
  std::map<std::string, Texts> plain;  // effect -> key -> value
  std::map<std::string, std::map<std::string, Texts>> qualified;
  out << YAML::Key << "params" << YAML::Value;
  if (!model.origin.empty()) {
    out << YAML::Comment("a priori (origin below), rounded from its 1σ");
  } else if (model.identified()) {
    out << YAML::Comment("identified: estimates rounded from their 1σ");
  }
  out << YAML::BeginMap;
  for (const auto& [name, value] : model.params) {
    const EffectEntry* owner = Effects().OwnerOf(name);
    const ParameterFamily* family = FamilyOf(name);
    const std::string text = ParameterNumber(model, name, value);
    if (family && family->name == param::kEtaPrefix) {
      eta[std::string(Qualifier(name))] = text;
    } else if (!owner || !family) {
      out << YAML::Key << name << YAML::Value << text;
    } else if (family->qualified()) {
      qualified[owner->name][std::string(family->file_key)][std::string(Qualifier(name))] = text;
    } else {
      plain[owner->name][name] = text;
    }
  }
  if (!eta.empty()) out << YAML::Key << "eta" << YAML::Value << eta;
  out << YAML::EndMap;
  for (const EffectEntry& e : Effects().entries()) {
    if (!plain.count(e.name) && !qualified.count(e.name)) continue;
    for (const EffectSetting& setting : e.settings) {
      const auto it = model.settings.find(std::string(setting.setting));
      if (it == model.settings.end()) continue;
      plain[e.name][std::string(setting.file_key)] = FileNumber(it->second);
    }
  }
  if (plain.empty() && qualified.empty()) return;
  out << YAML::Key << "effects" << YAML::Value << YAML::BeginMap;
  for (const EffectEntry& e : Effects().entries()) {
    if (!plain.count(e.name) && !qualified.count(e.name)) continue;
    out << YAML::Key << e.name << YAML::Value << YAML::BeginMap;
    for (const auto& [key, value] : plain[e.name]) out << YAML::Key << key << YAML::Value << value;
    for (const auto& [key, map] : qualified[e.name]) out << YAML::Key << key << YAML::Value << map;
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

// A DOF's model keys: params (and effects, settings), its σ, its origin.
void EmitModelKeys(YAML::Emitter& out, const DofParameters& model) {
  EmitModel(out, model);
  if (model.identified()) {
    out << YAML::Key << "sigma" << YAML::Value;
    EmitSigmas(out, model.sigma);
  }
  if (!model.origin.empty()) out << YAML::Key << "origin" << YAML::Value << model.origin;
}

void EmitDofs(YAML::Emitter& out, const Vehicle& v) {
  std::map<Dof, bool> dofs;
  for (const auto& [dof, prior] : v.priors) dofs[dof] = true;
  for (const auto& [dof, model] : v.models) dofs[dof] = true;
  if (dofs.empty()) return;
  out << YAML::Key << "dofs" << YAML::Value << YAML::BeginMap;
  for (const auto& [dof, unused] : dofs) {
    out << YAML::Key << std::string(DofName(dof)) << YAML::Value << YAML::BeginMap;
    if (const auto p = v.priors.find(dof); p != v.priors.end() && p->second.drag) {
      const DragPrior& d = *p->second.drag;
      out << YAML::Key << "drag" << YAML::Value;
      EmitFlowMap(out, {{"k", d.k}, {"kq", d.kq}, {"rel_sigma", d.rel_sigma}});
      out << YAML::Comment("a priori");
    }
    if (const auto p = v.priors.find(dof); p != v.priors.end() && p->second.added_mass) {
      out << YAML::Key << "added_mass" << YAML::Value;
      EmitPair(out, *p->second.added_mass);
    }
    if (const auto m = v.models.find(dof); m != v.models.end()) EmitModelKeys(out, m->second);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

// `comment` as YAML comment lines, one "# " line per line.
std::string CommentLines(const std::string& comment) {
  std::string text;
  std::size_t from = 0;
  while (from <= comment.size()) {
    const std::size_t end = std::min(comment.find('\n', from), comment.size());
    text += "# " + comment.substr(from, end - from) + "\n";
    from = end + 1;
  }
  return text;
}

// Lines of `text`, without their ends ("\n" or "\r\n").
std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t from = 0; from < text.size();) {
    const std::size_t end = std::min(text.find('\n', from), text.size());
    lines.push_back(text.substr(from, end - from));
    if (!lines.back().empty() && lines.back().back() == '\r') lines.back().pop_back();
    from = end + 1;
  }
  return lines;
}

// Emitted YAML (a map opened by `emit`) as lines, each indented by `indent` spaces.
template <typename Emit>
std::vector<std::string> EmittedLines(int indent, Emit emit) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  emit(out);
  out << YAML::EndMap;
  const std::string text = out.c_str();
  if (text == "{}") return {};
  std::vector<std::string> lines = Lines(text);
  for (std::string& l : lines) l.insert(0, static_cast<std::size_t>(indent), ' ');
  return lines;
}

// The indent of a line holding a key or value; -1 for a blank (spaces, tabs) or comment-only
// line.
int IndentOf(const std::string& line) {
  const std::size_t at = line.find_first_not_of(" \t");
  return at == std::string::npos || line[at] == '#' ? -1
                                                    : static_cast<int>(line.find_first_not_of(' '));
}

// The key a line at `indent` starts ("surge" of "  surge:  # …", of "  'surge' :"), and whether
// a value follows its colon on the line (a flow map or scalar).
std::pair<std::string, bool> KeyOf(const std::string& line, int indent) {
  const std::size_t colon = line.find(':', static_cast<std::size_t>(indent));
  if (colon == std::string::npos) return {"", false};
  std::string key =
      line.substr(static_cast<std::size_t>(indent), colon - static_cast<std::size_t>(indent));
  key.erase(key.find_last_not_of(" \t") + 1);
  if (key.size() >= 2 && (key.front() == '\'' || key.front() == '"') && key.back() == key.front())
    key = key.substr(1, key.size() - 2);
  const std::size_t rest = line.find_first_not_of(" \t", colon + 1);
  return {key, rest != std::string::npos && line[rest] != '#'};
}

// The end of the entry that starts at `from` (a key at `indent`): the next line with a key at
// `indent` or less, less the blank and comment lines just above it (they are that key's).
std::size_t EntryEnd(const std::vector<std::string>& lines, std::size_t from, int indent) {
  std::size_t end = from + 1;
  while (end < lines.size() && (IndentOf(lines[end]) < 0 || IndentOf(lines[end]) > indent)) ++end;
  if (end == lines.size()) return end;
  while (end > from + 1 && IndentOf(lines[end - 1]) < 0) --end;
  return end;
}

// The keys of a DOF's entry that are the user's a priori knowledge; the others are the model
// (params, effects, settings, sigma, origin), written anew from the vehicle.
bool IsAPrioriKey(const std::string& key) { return key == "drag" || key == "added_mass"; }

// Lines [from, end) of `lines` appended to `out`.
void Append(const std::vector<std::string>& lines, std::size_t from, std::size_t end,
            std::vector<std::string>* out) {
  using Diff = std::vector<std::string>::difference_type;
  out->insert(out->end(), lines.begin() + static_cast<Diff>(from),
              lines.begin() + static_cast<Diff>(end));
}

// One DOF's entry of a `dofs:` block, lines [from, end) with the DOF key at `indent`, into
// `out`: its a priori keys as written (comments kept), then `model`'s keys (none: null). False
// when a model is to go into an entry written as a flow map ("surge: {drag: …}"), which has no
// lines to merge into; such an entry without a model is kept as written.
bool MergeDofEntry(const std::vector<std::string>& lines, std::size_t from, std::size_t end,
                   int indent, const DofParameters* model, std::vector<std::string>* out) {
  if (KeyOf(lines[from], indent).second) {
    if (model) return false;
    Append(lines, from, end, out);
    return true;
  }
  out->push_back(lines[from]);
  int child = indent + 2;
  for (std::size_t k = from + 1; k < end; ++k) {
    if (IndentOf(lines[k]) > indent) {
      child = IndentOf(lines[k]);
      break;
    }
  }
  for (std::size_t k = from + 1; k < end;) {
    if (IndentOf(lines[k]) != child) {
      out->push_back(lines[k++]);
      continue;
    }
    const std::size_t next = EntryEnd(lines, k, child);
    if (IsAPrioriKey(KeyOf(lines[k], child).first)) Append(lines, k, next, out);
    k = next;
  }
  if (model) {
    const auto m = EmittedLines(child, [model](YAML::Emitter& e) { EmitModelKeys(e, *model); });
    out->insert(out->end(), m.begin(), m.end());
  }
  return true;
}

// The top-level `dofs:` block at lines [from, end), block style, merged with v: each DOF's a
// priori keys as written, its model (v.models) anew, DOFs of v.models without an entry added at
// its end. nullopt where a DOF entry or the block is a flow map.
std::optional<std::vector<std::string>> MergeDofsBlock(const std::vector<std::string>& lines,
                                                       std::size_t from, std::size_t end,
                                                       const Vehicle& v) {
  if (KeyOf(lines[from], 0).second) return std::nullopt;
  std::vector<std::string> out = {lines[from]};
  int indent = 2;
  for (std::size_t k = from + 1; k < end; ++k) {
    if (IndentOf(lines[k]) > 0) {
      indent = IndentOf(lines[k]);
      break;
    }
  }
  std::map<Dof, bool> written;
  for (std::size_t k = from + 1; k < end;) {
    if (IndentOf(lines[k]) != indent) {
      out.push_back(lines[k++]);
      continue;
    }
    const std::size_t next = EntryEnd(lines, k, indent);
    const std::optional<Dof> dof = ParseDof(KeyOf(lines[k], indent).first);
    const auto model = dof ? v.models.find(*dof) : v.models.end();
    if (!MergeDofEntry(lines, k, next, indent, model == v.models.end() ? nullptr : &model->second,
                       &out)) {
      return std::nullopt;
    }
    if (dof) written[*dof] = true;
    k = next;
  }
  for (const auto& entry : v.models) {
    if (written.count(entry.first)) continue;
    out.push_back(std::string(static_cast<std::size_t>(indent), ' ') +
                  std::string(DofName(entry.first)) + ":");
    const DofParameters& model = entry.second;
    const auto m =
        EmittedLines(2 * indent, [&model](YAML::Emitter& e) { EmitModelKeys(e, model); });
    out.insert(out.end(), m.begin(), m.end());
  }
  return out;
}

// `lines` (a vehicle file) with its top-level `dofs:` block merged with v (MergeDofsBlock), or
// replaced by v's where it cannot be merged, or v's added at the end where it has none.
std::vector<std::string> WithDofsOf(std::vector<std::string> lines, const Vehicle& v) {
  const auto is_dofs = [](const std::string& l) {
    return IndentOf(l) == 0 && KeyOf(l, 0).first == "dofs";
  };
  const auto first = std::find_if(lines.begin(), lines.end(), is_dofs);
  const std::vector<std::string> whole =
      EmittedLines(0, [&v](YAML::Emitter& e) { EmitDofs(e, v); });
  if (first == lines.end()) {
    if (!whole.empty()) lines.push_back("");
    lines.insert(lines.end(), whole.begin(), whole.end());
    return lines;
  }
  const std::size_t from = static_cast<std::size_t>(first - lines.begin());
  const std::size_t end = EntryEnd(lines, from, 0);
  const auto merged = MergeDofsBlock(lines, from, end, v);
  const std::vector<std::string>& block = merged ? *merged : whole;
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(from),
              lines.begin() + static_cast<std::ptrdiff_t>(end));
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(from), block.begin(), block.end());
  return lines;
}

}  // namespace

void WriteVehicleYamlOver(const std::string& path, const std::string& source, const Vehicle& v,
                          const std::string& comment) {
  std::string text = ReadFileText(source);
  const std::string bom = "\xEF\xBB\xBF";
  const bool has_bom = text.rfind(bom, 0) == 0;
  if (has_bom) text.erase(0, bom.size());
  const std::string line_end = text.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  std::vector<std::string> lines = Lines(text);
  // Written whole: a payload on a base, and a file in YAML documents (`---`, `...`), whose
  // block a line merge could put past the first document.
  const auto whole = [](const std::string& l) {
    return (IndentOf(l) == 0 && KeyOf(l, 0).first == "base") || l.rfind("---", 0) == 0 ||
           l.rfind("...", 0) == 0;
  };
  if (std::any_of(lines.begin(), lines.end(), whole)) {
    WriteVehicleYaml(path, v, comment);
    return;
  }
  // An earlier header (its comment lines, and the blank line that ends it here): replaced.
  const std::string written_by = "# " + std::string(kWrittenByPrefix);
  if (!lines.empty() && lines[0].rfind(written_by, 0) == 0) {
    auto header_end = std::find_if(lines.begin(), lines.end(),
                                   [](const std::string& l) { return l.empty() || l[0] != '#'; });
    if (header_end != lines.end() && header_end->empty()) ++header_end;
    lines.erase(lines.begin(), header_end);
  }
  std::string out = has_bom ? bom : "";
  for (const std::string& l : Lines(CommentLines(comment))) out += l + line_end;
  out += line_end;
  for (const std::string& l : WithDofsOf(std::move(lines), v)) out += l + line_end;
  WriteFileAtomically(path, out);
}

void WriteVehicleYaml(const std::string& path, const Vehicle& v, const std::string& comment) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  EmitBody(out, v);
  out << YAML::Key << "thrusters" << YAML::Value << YAML::BeginSeq;
  for (const auto& t : v.thrusters) EmitThruster(out, t);
  out << YAML::EndSeq;
  out << YAML::Key << "min_thrust" << YAML::Value << FileNumber(v.min_thrust);
  EmitSpeedLimits(out, v.speed_limits);
  EmitMappings(out, v);
  EmitDofs(out, v);
  EmitPerDof(out, "sensors", v.sensors, [&out](const DofSensors& s) {
    EmitSensor(out, "position", s.position);
    EmitSensor(out, "velocity", s.velocity);
  });
  out << YAML::EndMap;
  WriteFileAtomically(path, CommentLines(comment) + out.c_str() + "\n");
}

}  // namespace uuvplan::io
