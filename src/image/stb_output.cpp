#include "raytrace/image/stb_output.hpp"

#include <exception>

#include "raytrace/image/output_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

// An error waits in `failure` until stb has returned and freed its buffers: it cannot unwind through stb.
struct Sink {
  OutputFile& file;
  std::exception_ptr failure;
};

void toFile(void* context, void* data, int size) {
  auto* sink = static_cast<Sink*>(context);
  if (sink->failure) return;
  try {
    sink->file.write(data, size_t(size));
  } catch (...) {
    sink->failure = std::current_exception();
  }
}

}  // namespace

void writeWithStb(const std::string& path, const std::function<int(StbWriteFunc*, void*)>& encode) {
  OutputFile file(path);
  Sink sink{file, nullptr};
  const bool encoded = encode(toFile, &sink) != 0;
  if (sink.failure) std::rethrow_exception(sink.failure);
  // stb fails only where an allocation does.
  if (!encoded) throw Error("cannot write " + quote(path, kMaxQuotedPath) + ": out of memory to encode it");
  file.commit();
}

}  // namespace rt
