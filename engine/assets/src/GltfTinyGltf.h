#pragma once
// Includes tinygltf's declarations with the options TinyGltfImplementation.cpp compiles it with.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE_WRITE
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>
