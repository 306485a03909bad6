#include "sim/base/file_io.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace csm::io::detail {

std::string errorAt(std::string_view name, uint64_t offset, std::string_view message) {
  std::string text(name);
  text += ": byte ";
  text += std::to_string(offset);
  text += ": ";
  text += message;
  return text;
}

std::string floatText(float value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  std::ostringstream out;
  out << value;
  return out.str();
}

std::optional<std::vector<std::byte>> readFileBytes(const std::string& path, uint64_t maxBytes,
                                                    std::string* error) {
  auto fail = [&](const std::string& message) -> std::optional<std::vector<std::byte>> {
    if (error) *error = path + ": " + message;
    return std::nullopt;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("not a readable file");
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return fail("cannot get the file size: " + ec.message());
  if (size > maxBytes) {
    return fail("file of " + std::to_string(size) + " bytes exceeds the limit of " +
                std::to_string(maxBytes) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open for reading");
  std::vector<std::byte> bytes(static_cast<size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (static_cast<uint64_t>(in.gcount()) != size) {
    return fail("read " + std::to_string(in.gcount()) + " of " + std::to_string(size) + " bytes");
  }
  return bytes;
}

bool writeFileAtomically(const std::string& path, std::span<const std::byte> bytes,
                         std::string* error) {
  // A name of this process's own: two processes writing one path never share a half-written
  // temporary file.
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  auto fail = [&](const std::string& message) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    if (error) *error = path + ": " + message;
    return false;
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return fail("cannot open " + tmp + " for writing");
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) return fail("writing " + tmp + " failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) return fail("cannot rename " + tmp + ": " + ec.message());
  return true;
}

}  // namespace csm::io::detail

namespace csm {

std::string resolveRelative(const std::string& baseDir, const std::string& path) {
  if (path.empty() || baseDir.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(baseDir) / path).lexically_normal().string();
}

}  // namespace csm
