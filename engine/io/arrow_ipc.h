#pragma once
#include <cstdint>

namespace hdprior::arrow {

// Values of the Arrow IPC format (Schema.fbs and Message.fbs) that the feather reader and writer share.
inline constexpr int16_t kMetadataV4 = 3, kMetadataV5 = 4;
inline constexpr uint8_t kHeaderSchema = 1, kHeaderRecordBatch = 3;
inline constexpr uint8_t kTypeInt = 2, kTypeFloatingPoint = 3, kTypeUtf8 = 5, kTypeBool = 6, kTypeDecimal = 7;

// The bytes of a validity bitmap of `bits` bits.
inline int64_t bitmapBytes(int64_t bits) { return (bits + 7) / 8; }

}  // namespace hdprior::arrow
