#pragma once
// The single plane's item buffer (the paper's section 1.3) as a picture: each patch id in its own
// false colour, pixels that see nothing dark.
#include "solver/projection/item_buffer.h"
#include "viewer/image.h"

namespace radmesh {

Image falseColourImage(const ItemBuffer& buffer);

}  // namespace radmesh
