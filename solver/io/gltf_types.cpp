#include "solver/io/gltf_types.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

using nlohmann::json;

// What a property must be, by glTF 2.0's JSON schema.
enum class Kind {
  Index,     // an index or an enum: tinygltf reads it as an int, so 4294967297 became 1
  Size,      // a count or a byte size, which tinygltf reads as a size_t
  Number,
  String,
  Boolean,
  Numbers,   // exactly Rule::length numbers
  Indices,   // an array of Index
  IndexMap,  // an object whose values are Index (a primitive's attributes)
  Objects,   // an array of objects (the document's elements)
};

struct Rule {
  std::string_view key;   // dotted for a property of nested objects, each of which must be an object
  Kind kind;
  size_t length = 0;      // of Kind::Numbers
  bool required = false;  // refused when missing too, where tinygltf would ignore the absence
};

// Every element below but a primitive is one of glTF's "child of root" properties, whose optional
// name is a string: the Khronos validator reports `"name": 5` as a type mismatch.
constexpr Rule kName{"name", Kind::String};

// The properties radmesh reads, per element.
constexpr Rule kAccessor[] = {kName,
                              {"bufferView", Kind::Index},
                              {"byteOffset", Kind::Size},
                              {"componentType", Kind::Size},
                              {"count", Kind::Size},
                              {"type", Kind::String},
                              {"normalized", Kind::Boolean}};
constexpr Rule kBufferView[] = {
    kName, {"buffer", Kind::Index}, {"byteOffset", Kind::Size}, {"byteLength", Kind::Size}, {"byteStride", Kind::Size}};
constexpr Rule kBuffer[] = {kName, {"byteLength", Kind::Size}, {"uri", Kind::String}};
constexpr Rule kImage[] = {kName, {"uri", Kind::String}, {"bufferView", Kind::Index}, {"mimeType", Kind::String}};
constexpr Rule kTexture[] = {kName, {"source", Kind::Index}};
constexpr Rule kMaterial[] = {kName,
                              {"pbrMetallicRoughness.baseColorFactor", Kind::Numbers, 4},
                              {"pbrMetallicRoughness.baseColorTexture.index", Kind::Index},
                              {"emissiveFactor", Kind::Numbers, 3},
                              {"emissiveTexture.index", Kind::Index},
                              {"doubleSided", Kind::Boolean},
                              {"extensions.KHR_materials_emissive_strength.emissiveStrength", Kind::Number}};
constexpr Rule kMesh[] = {kName};
constexpr Rule kPrimitive[] = {
    {"attributes", Kind::IndexMap}, {"indices", Kind::Index}, {"material", Kind::Index}, {"mode", Kind::Index}};
constexpr Rule kNode[] = {kName,
                          {"mesh", Kind::Index},
                          {"children", Kind::Indices},
                          {"translation", Kind::Numbers, 3},
                          {"rotation", Kind::Numbers, 4},
                          {"scale", Kind::Numbers, 3},
                          {"matrix", Kind::Numbers, 16},
                          {"extensions.KHR_lights_punctual.light", Kind::Index, 0, true}};
constexpr Rule kScene[] = {kName, {"nodes", Kind::Indices}};
constexpr Rule kLight[] = {kName,
                           {"type", Kind::String},
                           {"intensity", Kind::Number},
                           {"range", Kind::Number},
                           {"color", Kind::Numbers, 3},
                           {"spot.innerConeAngle", Kind::Number},
                           {"spot.outerConeAngle", Kind::Number}};
constexpr Rule kDocument[] = {{"asset.version", Kind::String}, {"scene", Kind::Index}};

// An array of elements: its key (in the document, or in each element of the array whose `within`
// lists it), what its elements are called in messages, and their rules.
struct NamedArrays {
  std::string_view array;
  std::string_view label;
  std::span<const Rule> rules;
  std::span<const NamedArrays> within = {};  // arrays inside each element
};

constexpr NamedArrays kPrimitives[] = {{"primitives", "primitive", kPrimitive}};
constexpr NamedArrays kNamedArrays[] = {{"accessors", "accessor", kAccessor},
                                        {"bufferViews", "bufferView", kBufferView},
                                        {"buffers", "buffer", kBuffer},
                                        {"images", "image", kImage},
                                        {"textures", "texture", kTexture},
                                        {"materials", "material", kMaterial},
                                        {"meshes", "mesh", kMesh, kPrimitives},
                                        {"nodes", "node", kNode},
                                        {"scenes", "scene", kScene},
                                        {"extensions.KHR_lights_punctual.lights", "KHR_lights_punctual light", kLight}};

bool wholeNumber(const json& v, uint64_t most) { return v.is_number_unsigned() && v.get<uint64_t>() <= most; }
bool isIndex(const json& v) { return wholeNumber(v, std::numeric_limits<int>::max()); }
bool all(const json& v, bool (*each)(const json&)) { return std::all_of(v.begin(), v.end(), each); }

bool fits(const json& v, const Rule& rule) {
  switch (rule.kind) {
    case Kind::Index: return isIndex(v);
    case Kind::Size: return wholeNumber(v, std::numeric_limits<uint64_t>::max());
    case Kind::Number: return v.is_number();
    case Kind::String: return v.is_string();
    case Kind::Boolean: return v.is_boolean();
    case Kind::Numbers:
      return v.is_array() && v.size() == rule.length && all(v, [](const json& x) { return x.is_number(); });
    case Kind::Indices: return v.is_array() && all(v, isIndex);
    case Kind::IndexMap: return v.is_object() && all(v, isIndex);  // an object's iterators give its values
    case Kind::Objects: return v.is_array() && all(v, [](const json& x) { return x.is_object(); });
  }
  return false;
}

std::string wanted(const Rule& rule) {
  constexpr std::string_view kIndexRange = "from 0 to 2147483647";  // an int's
  switch (rule.kind) {
    case Kind::Index: return fmt::format("a whole number {}", kIndexRange);
    case Kind::Size: return "a whole number >= 0";
    case Kind::Number: return "a number";
    case Kind::String: return "a string";
    case Kind::Boolean: return "true or false";
    case Kind::Numbers: return fmt::format("{} numbers", rule.length);
    case Kind::Indices: return fmt::format("an array of whole numbers {}", kIndexRange);
    case Kind::IndexMap: return fmt::format("an object of whole numbers {}", kIndexRange);
    case Kind::Objects: return "an array of objects";
  }
  return {};
}

// The value as the file has it, cut short: a mistyped array may hold thousands of numbers. A
// signed zero is the file's -0 (a plain 0 is read as unsigned), which the JSON library writes as 0.
std::string shown(const json& value) {
  if (value.is_number_integer() && !value.is_number_unsigned() && value.get<std::int64_t>() == 0) return "-0";
  constexpr size_t kMaxChars = 60;
  const std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  return text.size() <= kMaxChars ? text : text.substr(0, kMaxChars) + "...";
}

// A whole value written as 3.0 or -0 fits no whole-number rule (glTF's and tinygltf's integers are
// unsigned JSON integers): the fix says how to write it.
std::string howToWrite(const json& value) {
  if (!value.is_number() || value.is_number_unsigned()) return "";
  const double v = value.get<double>();
  if (!(v >= 0.0 && v <= 9007199254740992.0 && v == std::floor(v))) return "";
  return fmt::format(": {}, without a decimal point or sign", static_cast<std::uint64_t>(v));
}

SceneError refusal(const std::string& path, const std::string& element, std::string_view key, const json& value,
                   const std::string& want) {
  return SceneError(path, element, fmt::format("{} is {} ({}), not {}", key, shown(value), value.type_name(), want),
                    fmt::format("give {} as {}{}", key, want, howToWrite(value)));
}

// The value of the dotted key in `object`, null when it (or an object on its way) is missing.
// An object on its way that is no object is refused: tinygltf would skip all below it.
const json* member(const std::string& path, const std::string& element, const json& object, const Rule& rule) {
  const json* at = &object;
  for (size_t start = 0;;) {
    const size_t dot = rule.key.find('.', start);
    const auto it = at->find(std::string(rule.key.substr(start, dot == std::string_view::npos ? dot : dot - start)));
    if (it == at->end()) {
      if (rule.required && dot == std::string_view::npos)
        throw SceneError(path, element, fmt::format("{} is missing (it must be {})", rule.key, wanted(rule)),
                         fmt::format("give {} as {}", rule.key, wanted(rule)));
      return nullptr;
    }
    if (dot == std::string_view::npos) return &*it;
    if (!it->is_object()) throw refusal(path, element, rule.key.substr(0, dot), *it, "an object");
    at = &*it;
    start = dot + 1;
  }
}

void checkRules(const std::string& path, const std::string& element, const json& object, std::span<const Rule> rules) {
  for (const Rule& rule : rules)
    if (const json* value = member(path, element, object, rule); value && !fits(*value, rule))
      throw refusal(path, element, rule.key, *value, wanted(rule));
}

// The array `elements` names in `parent` (the document, or one of its elements, labelled `owner`).
void checkNamedArrays(const std::string& path, const std::string& owner, const json& parent, const NamedArrays& elements) {
  const Rule array{elements.array, Kind::Objects};
  const json* list = member(path, owner, parent, array);
  if (!list) return;
  if (!fits(*list, array)) throw refusal(path, owner, elements.array, *list, wanted(array));
  for (size_t i = 0; i < list->size(); ++i) {
    const std::string label = (owner.empty() ? "" : owner + " ") + gltfElementLabel(elements.label, i, (*list)[i]);
    checkRules(path, label, (*list)[i], elements.rules);
    for (const NamedArrays& inner : elements.within) checkNamedArrays(path, label, (*list)[i], inner);
  }
}

}  // namespace

std::string gltfElementLabel(std::string_view kind, size_t index, const json& element) {
  const bool named = element.is_object() && element.contains("name") && element["name"].is_string();
  return fmt::format("{} {}{}", kind, index, named ? " '" + element["name"].get<std::string>() + "'" : "");
}

void checkGltfTypes(const std::string& path, const json& doc) {
  if (!doc.is_object()) return;
  checkRules(path, "", doc, kDocument);
  for (const NamedArrays& elements : kNamedArrays) checkNamedArrays(path, "", doc, elements);
}

}  // namespace radmesh
