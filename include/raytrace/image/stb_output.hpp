// The files stb_image_write encodes, written through an OutputFile.
#pragma once

#include <functional>
#include <string>

namespace rt {

// stb's stbi_write_func: receives the encoded file, in one or more pieces.
using StbWriteFunc = void(void* context, void* data, int size);

// Runs encode(func, context), an stbi_write_*_to_func call that returns stb's success, with func writing each
// piece straight to a temporary file, then renames it to `path`. Throws Error.
void writeWithStb(const std::string& path, const std::function<int(StbWriteFunc*, void*)>& encode);

}  // namespace rt
