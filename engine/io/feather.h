#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "engine/io/arrow_table.h"

namespace hdprior::arrow {

enum class Compression { None, Lz4Frame, Zstd };

// Feather v2 = the Arrow IPC file format. Strict: every offset and size is checked
// before it is used; anything malformed or unsupported throws Error naming `source`.
Table parseFeather(std::span<const uint8_t> bytes, const std::string& source);
Table readFeather(const std::filesystem::path& path);

// Writes one record batch per `rowsPerBatch` rows (0 = a single batch).
std::vector<uint8_t> serializeFeather(const Table& table, Compression compression = Compression::Lz4Frame,
                                      int64_t rowsPerBatch = 0);
// Atomic: temp file + rename.
void writeFeather(const std::filesystem::path& path, const Table& table,
                  Compression compression = Compression::Lz4Frame);

}  // namespace hdprior::arrow
