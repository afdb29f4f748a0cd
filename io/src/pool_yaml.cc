// The pool file (contract §Pool, docs/formats.md).
#include "uuvplan/io/pool_yaml.h"

#include <algorithm>
#include <filesystem>

#include "uuvplan/io/plausibility.h"
#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the pool file
namespace fs = std::filesystem;

namespace {

// A floor over 100 m across and over 100 times wider than the water is deep: length and width
// written in cm beside a depth in m (800 × 400 × 2.5), the slip CheckPlausibleLength cannot see
// in one number. CHOSEN: the widest pools built are about 50 m (an Olympic pool, 50 × 25 × 2 m,
// is 12.5 times wider than deep; a towing tank is narrower than it is long); a harbour or lake
// so planned is accepted with --accept-implausible.
void CheckFloorAgainstDepth(const MapValue& m, const Pool& pool) {
  const double narrow = std::min(pool.length, pool.width);
  if (!(narrow > 100 && narrow > 100 * pool.depth)) return;
  Implausible(m.Required(pool.width <= pool.length ? "width" : "length"),
              "a pool " + Significant(pool.length, 4) + " × " + Significant(pool.width, 4) +
                  " m and " + Significant(pool.depth, 3) + " m deep is " +
                  Significant(narrow / pool.depth, 3) +
                  " times wider than deep: are length and width in cm? " +
                  Significant(pool.length / 100, 4) + " × " + Significant(pool.width / 100, 4) +
                  " m would be a pool");
}

}  // namespace

Pool ReadPool(const std::string& path) {
  return Guarded(path, [&] {
    const MapValue m = LoadYamlMap(path, "a pool (name, length, width, depth, margin, max_turns)",
                                   "a map of pool keys");
    m.AllowOnly({"name", "length", "width", "depth", "margin", "max_turns"});
    Pool pool;
    const Value name = m.Optional("name");
    pool.name = name.absent() ? fs::path(path).stem().string() : Name(name, "a pool name");
    const auto dimension = [&m](const char* key, const InputQuantity& plausible) {
      const Value v = m.Required(key);
      const double x = Positive(v);
      CheckPlausibleLength(v, x, plausible);
      return x;
    };
    pool.length = dimension("length", plausible::kPoolDimension);
    pool.width = dimension("width", plausible::kPoolDimension);
    pool.depth = dimension("depth", plausible::kPoolDepth);
    CheckFloorAgainstDepth(m, pool);
    if (const Value margin = m.Optional("margin"); !margin.absent()) {
      pool.margin = NonNegative(margin);
      CheckPlausibleLength(margin, pool.margin, plausible::kPoolMargin);
      if (!(2 * pool.margin < std::min({pool.length, pool.width, pool.depth}))) {
        margin.Expected("a margin that leaves room to move (2·margin < length, width and depth)");
      }
    }
    if (const Value turns = m.Optional("max_turns"); !turns.absent()) {
      pool.max_turns = Positive(turns);
    }
    return pool;
  });
}

}  // namespace uuvplan::io
