// Fuzz harness: a checkpoint (io/checkpoint.h: decode_checkpoint, the bytes
// load_checkpoint reads from checkpoint.bin or specimen.bin). Its checksum
// refuses almost every random change, so the harness also feeds the bytes
// with the checksum made right (fuzz/checkpoint_checksum.h): the decoder
// behind the checksum is what is fuzzed. See harness_input.h.
#include "fuzz/checkpoint_checksum.h"
#include "fuzz/harness_input.h"
#include "io/checkpoint.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> as_given(data, data + size);
  grainlab::fuzz::refused_or_read([&] { grainlab::decode_checkpoint(as_given, "fuzz.bin"); });
  const std::vector<std::uint8_t> resealed = grainlab::fuzz::with_right_checksum(as_given);
  return grainlab::fuzz::refused_or_read([&] { grainlab::decode_checkpoint(resealed, "fuzz.bin"); });
}
