#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace hdprior {

// Reads a whole file; throws Error naming the file if it is missing or unreadable.
std::vector<uint8_t> readFileBytes(const std::filesystem::path& path);
std::string readFileText(const std::filesystem::path& path);

// Writes to a temporary name beside `path` and renames it into place, so a reader
// never sees a half-written file. Throws Error on failure and leaves nothing behind.
void writeFileAtomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace hdprior
