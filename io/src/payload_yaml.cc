// A vehicle file that is a payload on a known vehicle (docs/formats.md "A payload on a known
// vehicle"): `base` names the base vehicle file, `payload` what is added to it
// (model/payload.h).
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "uuvplan/io/plausibility.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/payload.h"
#include "vehicle_keys.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the vehicle file

namespace {

// The base files being read, outermost first (a file met twice is a cycle).
thread_local std::vector<std::string> open_bases;

// A cycle of bases, reported once at the file that closes it (not wrapped by each file of the
// cycle on the way out).
struct BaseCycle : InputError {
  using InputError::InputError;
};

// "<mapping>.<pos|neg>" of one of the base's mappings.
std::string Blocked(const Value& v, const Vehicle& base) {
  const std::string text = Name(v, "<mapping>.<pos|neg>");
  const auto q = ParseEtaQualifier(text);
  if (!q || base.MappingIndex(q->first) < 0) {
    v.Expected("<mapping>.<pos|neg> of one of the base's mappings");
  }
  return text;
}

Payload ParsePayload(const Value& v, const Vehicle& base) {
  const MapValue m(v, "a payload {mass, volume, size, cg, added_mass, blocks}");
  m.AllowOnly({"mass", "volume", "size", "cg", "added_mass", "blocks"});
  Payload p;
  const Value mass = m.Required("mass"), volume = m.Required("volume");
  p.mass = Positive(mass);
  CheckPlausible(mass, p.mass, plausible::kVehicleMass);
  p.volume = Positive(volume);
  CheckPlausible(volume, p.mass / p.volume, plausible::kPayloadDensity);
  const Value size = m.Required("size");
  p.size = Triple(size, "[length, width, height] in m");
  for (double side : p.size) {
    if (!(side > 0)) size.Expected("[length, width, height] in m, each > 0");
    CheckPlausible(size, side, plausible::kVehicleSize);
  }
  const double base_size = *std::max_element(base.size.begin(), base.size.end());
  if (const Value cg = m.Optional("cg"); !cg.absent()) {
    p.cg = Triple(cg, "[x, y, z] in m from the base's centre (x forward, z down)");
    for (double x : p.cg)
      CheckPlausible(cg, std::abs(x) / base_size, plausible::kPayloadOffsetRatio);
  }
  p.added_mass = base.added_mass;
  if (const Value a = m.Optional("added_mass"); !a.absent()) p.added_mass = AddedMassBounds(a);
  if (const Value b = m.Optional("blocks"); !b.absent()) {
    for (const Value& item : List(b, "a list of <mapping>.<pos|neg>")) {
      p.blocks.push_back(Blocked(item, base));
    }
  }
  return p;
}

// The base vehicle file `v` names, its faults reported through the key that names it.
Vehicle ReadBase(const Value& v) {
  const std::string path = ReadableFile(v);
  const std::string file = std::filesystem::weakly_canonical(path).string();
  if (std::find(open_bases.begin(), open_bases.end(), file) != open_bases.end()) {
    std::string chain;
    for (const std::string& f : open_bases) chain += f + " → ";
    try {
      v.Fail("the bases return to a file already read: " + chain + file);
    } catch (const InputError& e) {
      throw BaseCycle(e.what());
    }
  }
  open_bases.push_back(file);
  try {
    Vehicle base = ReadVehicle(path);
    open_bases.pop_back();
    return base;
  } catch (const BaseCycle&) {
    open_bases.pop_back();
    throw;
  } catch (const InputError& e) {
    open_bases.pop_back();
    v.Fail(std::string("the base vehicle is not valid: ") + e.what());
  }
}

}  // namespace

Vehicle ParsePayloadVehicle(const MapValue& root, bool truth) {
  // The outermost file opens the chain (a cycle back to it is found at once).
  const bool outermost = open_bases.empty();
  if (outermost)
    open_bases.push_back(std::filesystem::weakly_canonical(root.self().file()).string());
  struct Close {
    bool active;
    ~Close() {
      if (active) open_bases.clear();
    }
  } close{outermost};
  if (truth) {
    root.AllowOnly({"name", "base", "payload", "sensors", "dofs", "virtual_pool"});
  } else {
    root.AllowOnly({"name", "base", "payload", "sensors"});
  }
  const Value base_key = root.Required("base");
  const Vehicle base = ReadBase(base_key);
  const std::string name = Name(root.Required("name"), "a vehicle name");
  const Payload payload = ParsePayload(root.Required("payload"), base);
  Vehicle vehicle = WithPayload(base, payload, name,
                                "the estimates of base " + base.name + " (" +
                                    base_key.node().Scalar() + ") with the payload's rules");
  if (const Value v = root.Optional("sensors"); !v.absent()) ParseSensors(v, &vehicle);
  return vehicle;
}

}  // namespace uuvplan::io
