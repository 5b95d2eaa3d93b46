// tinyobjloader's parser (Debian's libtinyobjloader-dev header), compiled here instead of linked
// from its shared library so that it carries the fuzzer's coverage instrumentation and the
// sanitizers' checks.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
