// A device file that includes an engine header: runs up the layers.

#include "engine/core/Mesh.h"
