// The pool file (contract §Pool, docs/formats.md).
#include "uuvplan/io/pool_yaml.h"

#include <algorithm>
#include <filesystem>

#include "uuvplan/io/plausibility.h"
#include "uuvplan/io/yaml_value.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the pool file
namespace fs = std::filesystem;

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
