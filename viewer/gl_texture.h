#pragma once
// An RGBA8 texture in the current GL context, for pictures drawn by the panel.
#include "viewer/image.h"

namespace radmesh {

class GlTexture {
 public:
  GlTexture();  // needs a current context, as does everything below
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  void upload(const Image& image);  // nearest-neighbour sampling: item-buffer pixels stay square
  unsigned id() const { return id_; }

 private:
  unsigned id_ = 0;
};

}  // namespace radmesh
