#include "recording/message_definition.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io::recording {
namespace {

using model::InputError;

std::string Trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

bool IsSeparator(const std::string& line) {
  return line.size() >= 3 && line.find_first_not_of('=') == std::string::npos;
}

// A field's type as written (`Vector3`, `Header`, `geometry_msgs/Vector3`) as pkg/Type.
std::string ResolvedType(const std::string& written, const std::string& package) {
  if (PrimitiveSize(written) >= 0 || written == "wstring") return written;
  if (written.find('/') != std::string::npos) return NormalisedType(written);
  if (written == "Header") return "std_msgs/Header";  // ROS 1 msg convention
  return package + "/" + written;
}

// `float64[]`, `uint8[4]`, `int32[<=5]`, `string<=10` into the field's type and array shape.
void ParseTypeText(std::string text, FieldDefinition* field, const std::string& where) {
  const auto bracket = text.find('[');
  if (bracket != std::string::npos && text.back() != ']') {
    throw InputError(where,
                     "expected an array type T[], T[N] or T[<=N] in the message "
                     "definition, got '" +
                         text + "'");
  }
  if (bracket != std::string::npos) {
    const std::string bound = text.substr(bracket + 1, text.size() - bracket - 2);
    field->array = true;
    if (!bound.empty() && bound.rfind("<=", 0) != 0) {
      char* end = nullptr;
      const long n = std::strtol(bound.c_str(), &end, 10);
      if (*end != '\0' || n < 0 || n > 1 << 24 || text.back() != ']') {
        throw InputError(where,
                         "expected an array type T[], T[N] or T[<=N] in the message definition, "
                         "got '" +
                             text + "'");
      }
      field->fixed_length = int(n);
    }
    text = text.substr(0, bracket);
  }
  const auto bounded = text.find("<=");  // bounded string
  field->type = bounded == std::string::npos ? text : text.substr(0, bounded);
}

// The fields of one section; constants (`NAME=value`) are skipped.
std::vector<FieldDefinition> ParseFields(const std::vector<std::string>& lines,
                                         const std::string& package, const std::string& where) {
  std::vector<FieldDefinition> fields;
  for (const std::string& raw : lines) {
    const std::string line = Trimmed(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string type_text, name;
    words >> type_text >> name;
    std::string rest;
    words >> rest;
    // A constant is `TYPE NAME=VALUE` (or `NAME = VALUE`); `TYPE NAME VALUE` is a field with a
    // default (ROS 2), and `T[<=N]`, `string<=N` are bounded types, not constants.
    if (name.empty() || name.find('=') != std::string::npos || rest.rfind('=', 0) == 0) continue;
    FieldDefinition field;
    field.name = name;
    ParseTypeText(type_text, &field, where);
    field.type = ResolvedType(field.type, package);
    fields.push_back(field);
  }
  return fields;
}

std::string PackageOf(const std::string& type) { return type.substr(0, type.find('/')); }

// The least bytes a value of `type` takes (ROS 1 packing; CDR adds only padding), found depth
// first with each type's result kept: a type met again before its result is known contains
// itself (no finite serialisation); nesting deeper than kMaxDepth is refused too (the decoder
// recurses once per level).
std::size_t MinimumSize(MessageDefinitions* d, const std::string& type, int depth,
                        const std::string& where) {
  constexpr int kMaxDepth = 64;
  const auto known = d->min_size.find(type);
  if (known != d->min_size.end()) {
    if (known->second != kUnknownSize) return known->second;
    throw InputError(
        where, "expected a message definition without cycles, got " + type + " containing itself");
  }
  if (depth > kMaxDepth) {
    throw InputError(where, "expected messages nested at most " + std::to_string(kMaxDepth) +
                                " deep, got " + type + " deeper");
  }
  d->min_size[type] = kUnknownSize;
  std::size_t bytes = 0;
  for (const FieldDefinition& f : d->types.at(type)) {
    const int primitive = PrimitiveSize(f.type);
    const std::size_t item = primitive > 0    ? std::size_t(primitive)
                             : primitive == 0 ? 4  // a string: its length
                                              : MinimumSize(d, f.type, depth + 1, where);
    if (!f.array)
      bytes += item;
    else
      bytes += f.fixed_length >= 0 ? std::size_t(f.fixed_length) * item : 4;
  }
  return d->min_size[type] = bytes;
}

void CheckTypesKnown(const MessageDefinitions& d, const std::string& where) {
  for (const auto& [type, fields] : d.types) {
    for (const FieldDefinition& f : fields) {
      if (PrimitiveSize(f.type) >= 0 || d.types.count(f.type)) continue;
      throw InputError(where, "expected a definition of every type " + d.root + " uses, got " +
                                  f.type + " (field " + type + "." + f.name + ") undefined");
    }
  }
}

}  // namespace

std::string NormalisedType(const std::string& type) {
  const auto msg = type.find("/msg/");
  return msg == std::string::npos ? type : type.substr(0, msg) + type.substr(msg + 4);
}

int PrimitiveSize(const std::string& type) {
  static const std::map<std::string, int> kSizes = {
      {"bool", 1},    {"int8", 1},  {"uint8", 1},    {"byte", 1},    {"char", 1},  {"int16", 2},
      {"uint16", 2},  {"int32", 4}, {"uint32", 4},   {"float32", 4}, {"int64", 8}, {"uint64", 8},
      {"float64", 8}, {"time", 8},  {"duration", 8}, {"string", 0}};
  const auto it = kSizes.find(type);
  return it == kSizes.end() ? -1 : it->second;
}

MessageDefinitions ParseDefinitions(const std::string& type, const std::string& text,
                                    const std::string& where) {
  MessageDefinitions d;
  d.root = NormalisedType(type);
  std::string section = d.root;
  std::vector<std::string> lines;
  auto close_section = [&] { d.types[section] = ParseFields(lines, PackageOf(section), where); };
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (IsSeparator(Trimmed(line))) {
      close_section();
      lines.clear();
      section.clear();
    } else if (section.empty() && Trimmed(line).rfind("MSG:", 0) == 0) {
      section = NormalisedType(Trimmed(Trimmed(line).substr(4)));
    } else if (!section.empty()) {
      lines.push_back(line);
    }
  }
  if (!section.empty()) close_section();
  if (!d.types.count(d.root)) {
    throw InputError(where, "expected a message definition of " + d.root + ", got " +
                                (d.types.empty() ? "none" : "only " + d.types.begin()->first));
  }
  CheckTypesKnown(d, where);
  MinimumSize(&d, d.root, 0, where);
  return d;
}

}  // namespace uuvplan::io::recording
