#include "solver/io/gltf_accessor.h"

#include <cmath>
#include <cstring>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

// Where an accessor's elements are: checked so that every element lies inside its buffer view
// and the view inside its buffer.
struct ElementSpan {
  const unsigned char* first = nullptr;
  size_t count = 0;
  size_t stride = 0;
};

std::string accessorLabel(const tinygltf::Model& model, int index, const std::string& use) {
  std::string label = "accessor " + std::to_string(index);
  if (index >= 0 && static_cast<size_t>(index) < model.accessors.size() && !model.accessors[index].name.empty())
    label += " '" + model.accessors[index].name + "'";
  return use.empty() ? label : label + " (" + use + ")";
}

ElementSpan locate(const tinygltf::Model& model, int index, int type, const std::string& file,
                   const std::string& element) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
    throw SceneError(file, element,
                     "does not exist (the file has " + std::to_string(model.accessors.size()) + " accessors)",
                     "refer to an existing accessor");
  const tinygltf::Accessor& a = model.accessors[index];
  if (a.sparse.isSparse)
    throw SceneError(file, element, "is sparse, which radmesh does not read",
                     "export the model without sparse accessors");
  if (a.type != type)
    throw SceneError(file, element,
                     "has " + std::to_string(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type))) +
                         " components per element where " +
                         std::to_string(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type))) +
                         " are needed",
                     "store positions as VEC3 and indices as SCALAR");
  if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model.bufferViews.size())
    throw SceneError(file, element, "has no valid bufferView (" + std::to_string(a.bufferView) + ")",
                     "store the accessor's data in an existing bufferView");
  const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
  const std::string viewElement = "bufferView " + std::to_string(a.bufferView);
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
    throw SceneError(file, viewElement, "refers to buffer " + std::to_string(view.buffer) + ", which does not exist",
                     "refer to an existing buffer");
  const size_t bufferBytes = model.buffers[view.buffer].data.size();
  if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset)
    throw SceneError(file, viewElement,
                     "spans bytes " + std::to_string(view.byteOffset) + " to " +
                         std::to_string(view.byteOffset + view.byteLength) + " of buffer " +
                         std::to_string(view.buffer) + ", which holds " + std::to_string(bufferBytes),
                     "correct byteOffset or byteLength, or supply the whole buffer");
  const int componentBytes = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
  const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  if (componentBytes <= 0 || components <= 0)
    throw SceneError(file, element, "has an unknown component type " + std::to_string(a.componentType),
                     "use a component type defined by glTF 2.0");
  const size_t elementBytes = static_cast<size_t>(componentBytes) * static_cast<size_t>(components);
  const size_t stride = view.byteStride ? view.byteStride : elementBytes;
  if (stride < elementBytes)
    throw SceneError(file, viewElement,
                     "has byteStride " + std::to_string(stride) + ", smaller than the " +
                         std::to_string(elementBytes) + "-byte elements of " + element,
                     "set byteStride to at least the element size, or omit it");
  // The last element must end inside the view; compared by division so no product overflows.
  const bool fits = a.count == 0 ||
                    (a.byteOffset <= view.byteLength && elementBytes <= view.byteLength - a.byteOffset &&
                     (a.count - 1) <= (view.byteLength - a.byteOffset - elementBytes) / stride);
  if (!fits)
    throw SceneError(file, element,
                     "reads " + std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                         " of " + viewElement + ", which holds only " + std::to_string(view.byteLength) + " bytes",
                     "correct the accessor's count or byteOffset, or the bufferView's byteLength");
  const unsigned char* base = model.buffers[view.buffer].data.data();
  return {base + view.byteOffset + a.byteOffset, a.count, stride};
}

}  // namespace

std::vector<Vec3> readFloatVec3(const tinygltf::Model& model, int index, const std::string& file,
                                const std::string& use) {
  const std::string element = accessorLabel(model, index, use);
  const ElementSpan span = locate(model, index, TINYGLTF_TYPE_VEC3, file, element);
  if (model.accessors[index].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw SceneError(file, element,
                     "holds component type " + std::to_string(model.accessors[index].componentType) +
                         " where float (5126) positions are needed",
                     "export positions as 32-bit floats (no quantization)");
  std::vector<Vec3> out(span.count);
  for (size_t i = 0; i < span.count; ++i) {
    float xyz[3];
    std::memcpy(xyz, span.first + i * span.stride, sizeof xyz);  // elements need not be aligned
    if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
      throw SceneError(file, element,
                       "element " + std::to_string(i) + " has a NaN or infinite coordinate",
                       "give every vertex finite coordinates");
    out[i] = Vec3(xyz[0], xyz[1], xyz[2]);
  }
  return out;
}

std::vector<Rgb> readColours(const tinygltf::Model& model, int index, const std::string& file, const std::string& use) {
  const std::string element = accessorLabel(model, index, use);
  const int type = index >= 0 && static_cast<size_t>(index) < model.accessors.size() ? model.accessors[index].type : 0;
  const ElementSpan span = locate(model, index, type == TINYGLTF_TYPE_VEC4 ? type : TINYGLTF_TYPE_VEC3, file, element);
  const int component = model.accessors[index].componentType;
  if (component != TINYGLTF_COMPONENT_TYPE_FLOAT && component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
    throw SceneError(file, element, "holds colours of component type " + std::to_string(component),
                     "export colours as floats or normalized unsigned bytes or shorts");
  std::vector<Rgb> out(span.count);
  for (size_t i = 0; i < span.count; ++i)
    for (int c = 0; c < 3; ++c) {
      const unsigned char* p = span.first + i * span.stride;
      if (component == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        float v;
        std::memcpy(&v, p + c * sizeof v, sizeof v);
        if (!std::isfinite(v))
          throw SceneError(file, element, "element " + std::to_string(i) + " is NaN or infinite",
                           "give every vertex a finite colour");
        out[i][c] = v;
      } else if (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t v;
        std::memcpy(&v, p + c * sizeof v, sizeof v);
        out[i][c] = v / 65535.0;
      } else {
        out[i][c] = p[c] / 255.0;
      }
    }
  return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, const std::string& file,
                                  const std::string& use) {
  const std::string element = accessorLabel(model, index, use);
  const ElementSpan span = locate(model, index, TINYGLTF_TYPE_SCALAR, file, element);
  const int type = model.accessors[index].componentType;
  if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw SceneError(file, element,
                     "holds indices of component type " + std::to_string(type) +
                         " where unsigned byte, short or int are needed",
                     "export indices as unsigned 8, 16 or 32-bit integers");
  std::vector<uint32_t> out(span.count);
  for (size_t i = 0; i < span.count; ++i) {
    const unsigned char* p = span.first + i * span.stride;
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
      out[i] = *p;
    } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      uint16_t v;
      std::memcpy(&v, p, sizeof v);
      out[i] = v;
    } else {
      std::memcpy(&out[i], p, sizeof(uint32_t));
    }
  }
  return out;
}

}  // namespace radmesh
