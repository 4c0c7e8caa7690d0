// tinygltf (and the stb it calls) compiled into the fuzzer, instrumented like the rest: the same header version
// vkmc links as Debian's libtinygltf.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
