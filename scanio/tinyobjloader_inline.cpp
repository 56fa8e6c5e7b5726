// tinyobjloader's implementation, compiled from its header where Debian's shared library is not for the target
// (the Windows cross build); natively the library of libtinyobjloader-dev is linked instead.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
