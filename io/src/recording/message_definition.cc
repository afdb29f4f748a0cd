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
    if (name.empty() || line.find('=') != std::string::npos) continue;
    FieldDefinition field;
    field.name = name;
    ParseTypeText(type_text, &field, where);
    field.type = ResolvedType(field.type, package);
    fields.push_back(field);
  }
  return fields;
}

std::string PackageOf(const std::string& type) { return type.substr(0, type.find('/')); }

// A type that contains itself (directly or through others) has no finite serialisation.
bool ContainsItself(const MessageDefinitions& d, const std::string& type,
                    std::vector<std::string>* path) {
  if (std::find(path->begin(), path->end(), type) != path->end()) return true;
  path->push_back(type);
  for (const FieldDefinition& f : d.types.at(type)) {
    if (PrimitiveSize(f.type) < 0 && ContainsItself(d, f.type, path)) return true;
  }
  path->pop_back();
  return false;
}

void CheckTypesKnown(const MessageDefinitions& d, const std::string& where) {
  for (const auto& [type, fields] : d.types) {
    for (const FieldDefinition& f : fields) {
      if (PrimitiveSize(f.type) >= 0 || d.types.count(f.type)) continue;
      throw InputError(where, "the definition of " + d.root + " uses type " + f.type + " (field " +
                                  type + "." + f.name + ") without defining it");
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
  if (!d.types.count(d.root)) throw InputError(where, "expected a message definition of " + d.root);
  CheckTypesKnown(d, where);
  std::vector<std::string> path;
  if (ContainsItself(d, d.root, &path)) {
    throw InputError(where, "expected a message definition without cycles, got " + path.back() +
                                " containing itself");
  }
  return d;
}

}  // namespace uuvplan::io::recording
