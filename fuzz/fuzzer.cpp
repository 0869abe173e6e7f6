// libFuzzer entry point; RT_FUZZ_TARGET (scene, ply or cli) picks the function of targets.h.
#include "fuzz/targets.h"

#define RT_CONCAT(a, b) a##b
#define RT_FUZZ_FUNCTION(name) RT_CONCAT(rt::fuzz_, name)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  RT_FUZZ_FUNCTION(RT_FUZZ_TARGET)(data, size);
  return 0;
}
