// viscoroll: the limits on input read from files and lists (docs/errors.md, "Limits"), each
// checked before any work, and the bounded read of a file that enforces them.
//
// A limit bounds the memory and time an input can make the library take; each is far beyond what
// a real input needs. A file must be a regular file: a FIFO would block the reader, and a device
// such as /dev/zero never ends.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace viscoroll {

/// The input limits, in one place.
namespace limits {

/// Bytes of a scene file (viscoroll-solve --scene, Python Scene.from_json). The shipped scene
/// files have 0.7 to 1.8 kB; one of 1 MiB (80000 speeds) is parsed in 0.05 s and 6 MB.
inline constexpr std::size_t scene_file_bytes = std::size_t(1) << 20;

/// Bytes of a DMA CSV file (read_dma_csv_file, a scene file's material.dma). A measured data set
/// has tens to a few hundred rows of about 30 bytes (the shipped ones 8 and 15 kB); 1 MiB holds
/// about 35000, whose fit builds a design matrix of 2 rows per point and one column per
/// relaxation time: 17 MB at 30 times.
inline constexpr std::size_t dma_file_bytes = std::size_t(1) << 20;

/// Speeds of one sweep (a scene file's speeds, viscoroll-solve --speed, Python's speeds). Every
/// solution of a sweep is held until it ends: measured on the paper's scene, 2.6 kB a line and
/// 9 kB a bem solution (default grid) in viscoroll-solve, 3.5 kB and 20 kB in Python; so 100000
/// speeds hold up to 0.35 GB (line) and 2 GB (bem, Python).
inline constexpr std::size_t speeds = 100000;

}  // namespace limits

namespace detail {

/// "1 MiB" for a whole number of MiB, else "<n> bytes".
inline std::string byte_size(std::size_t bytes) {
  constexpr std::size_t mib = std::size_t(1) << 20;
  return bytes % mib == 0 ? std::to_string(bytes / mib) + " MiB" : std::to_string(bytes) + " bytes";
}

/// The message for `count` values of the list `name` over `limit`, or empty within it:
/// "speeds has 100001 values, over the limit of 100000 (docs/errors.md, "Limits")".
inline std::string count_over_limit(std::string_view name, std::size_t count, std::size_t limit) {
  if (count <= limit) return {};
  return std::string(name) + " has " + std::to_string(count) + " values, over the limit of " +
         std::to_string(limit) + " (docs/errors.md, \"Limits\")";
}

/// The text of the file `path`, a `kind` ("scene file", "DMA CSV file") of at most `max_bytes`.
/// Checks the file's type and size before opening it and reads at most max_bytes + 1 bytes, so a
/// file that grows meanwhile cannot exceed the limit. `fail(message)` must throw; it is called
/// with "no such file", "is a directory, not a <kind>", "is a FIFO, not a regular file (a <kind>
/// must be one)" (likewise a character or block device, a socket), "size = <n> bytes is over the
/// limit of <limit> for a <kind>", "cannot be opened for reading" or "cannot be read".
template <class Fail>
std::string read_bounded_file(const std::filesystem::path& path, std::size_t max_bytes,
                              std::string_view kind, const Fail& fail) {
  namespace fs = std::filesystem;
  const std::string what(kind);
  const auto over = [&](std::uintmax_t size) {
    fail("size = " + std::to_string(size) + " bytes is over the limit of " + byte_size(max_bytes) +
         " for a " + what);
  };
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) fail("no such file");
  if (fs::is_directory(status)) fail("is a directory, not a " + what);
  if (!fs::is_regular_file(status)) {
    const char* type = fs::is_fifo(status)             ? "a FIFO"
                       : fs::is_character_file(status) ? "a character device"
                       : fs::is_block_file(status)     ? "a block device"
                       : fs::is_socket(status)         ? "a socket"
                                                       : "a special file";
    fail("is " + std::string(type) + ", not a regular file (a " + what + " must be one)");
  }
  if (const auto size = fs::file_size(path, ec); !ec && size > max_bytes) over(size);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot be opened for reading");
  std::string text(max_bytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) fail("cannot be read");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > max_bytes) over(text.size());  // grew since its size was taken
  return text;
}

}  // namespace detail
}  // namespace viscoroll
