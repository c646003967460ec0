// One libFuzzer executable per target: CMake compiles this file once per name in fuzz/targets.hpp
// with SPHDECK_FUZZ_TARGET set to the function to call.
#include <cstddef>
#include <cstdint>

#include "fuzz/targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    sphdeck::fuzz::SPHDECK_FUZZ_TARGET(data, size);
    return 0;
}
