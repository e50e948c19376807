#include "emulator/transport.h"

namespace radmesh::emu {

const char* toString(Channel channel) {
  static constexpr const char* kNames[] = {"xnet", "router", "reduce", "scan", "sort", "front end"};
  return kNames[static_cast<int>(channel)];
}

}  // namespace radmesh::emu
