#pragma once
// How many bytes a T occupies in an MP-1 PE's memory and on its links. By default its host size;
// a program whose host type is larger than what the machine would hold (a handle standing for an
// immutable record, doubles the MP-1 would keep as floats) specializes WireSize for that type,
// saying why, and both memory and communication are charged at that size.
#include <cstdint>

namespace radmesh::emu {

template <class T>
struct WireSize {
  static constexpr std::int64_t bytes = sizeof(T);
};

template <class T>
inline constexpr std::int64_t kWireBytes = WireSize<T>::bytes;

}  // namespace radmesh::emu
