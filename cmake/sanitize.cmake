# RT_SANITIZE=ON builds everything with AddressSanitizer and UndefinedBehaviorSanitizer;
# with clang it also adds libFuzzer's coverage hooks so fuzz/ can build its fuzzers from the
# same objects. The default suite builds such a tree under build/sanitize (fuzz/CMakeLists.txt).
option(RT_SANITIZE "Build with AddressSanitizer + UndefinedBehaviorSanitizer (and libFuzzer hooks under clang)" OFF)
if(RT_SANITIZE)
  # Every UB report aborts the test that caused it; frame pointers give readable stacks.
  set(RT_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all
                        -fno-omit-frame-pointer)
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    list(APPEND RT_SANITIZE_FLAGS -fsanitize=fuzzer-no-link)
  endif()
  add_compile_options(${RT_SANITIZE_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()
