# Sanitizer and fuzzing builds (docs/reliability.md gives the commands).
#
#   -DSANITIZE=address,undefined   AddressSanitizer + UndefinedBehaviorSanitizer
#   -DSANITIZE=thread              ThreadSanitizer (the DDS tests)
#   -DSCANFILTER_FUZZ=ON           libFuzzer targets in fuzz/ (clang only)
#
# The flags go on every target of the project, so the library, the tools, the
# services and the tests are all instrumented. Any undefined behaviour aborts
# (-fno-sanitize-recover): a report is a failure, never a line in a log.
set(SANITIZE "" CACHE STRING "Sanitizers for the whole build: address,undefined or thread (empty: none)")
option(SCANFILTER_FUZZ "Build the libFuzzer targets in fuzz/ (needs clang)" OFF)

if(SANITIZE)
  if(SANITIZE MATCHES "thread" AND SANITIZE MATCHES "address")
    message(FATAL_ERROR "SANITIZE: ThreadSanitizer cannot be combined with AddressSanitizer")
  endif()
  set(SCANFILTER_SANITIZE_FLAGS -fsanitize=${SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  if(SANITIZE MATCHES "undefined" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC leaves these out of "undefined"; clang has them in it.
    list(APPEND SCANFILTER_SANITIZE_FLAGS -fsanitize=float-cast-overflow)
  endif()
  add_compile_options(${SCANFILTER_SANITIZE_FLAGS})
  add_link_options(${SCANFILTER_SANITIZE_FLAGS})
  # Debug info for readable reports, optimised enough to run the suite in time.
  add_compile_options(-g1)
endif()

if(SCANFILTER_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SCANFILTER_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  # Coverage instrumentation for all the code the fuzzers reach; the fuzz
  # executables add libFuzzer's main (fuzz/CMakeLists.txt).
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
