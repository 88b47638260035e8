# GSPH_FUZZ: the libFuzzer build of tests/fuzz (scripts/fuzz, docs/testing.md). Every target of
# the project (the library gsph, gsph_solver_core, gsph_preproc, ...) is compiled with the
# fuzzer's coverage instrumentation and ASan + UBSan; only the fuzz executables link libFuzzer.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 14)
  message(FATAL_ERROR "GSPH_FUZZ needs clang++-14 (-DCMAKE_CXX_COMPILER=clang++-14 "
                      "-DCMAKE_C_COMPILER=clang-14; scripts/fuzz installs it)")
endif()
if(GSPH_SANITIZE)
  message(FATAL_ERROR "GSPH_FUZZ already builds with ASan + UBSan; leave GSPH_SANITIZE off")
endif()
# An undefined-behaviour report must stop the run, or libFuzzer never records the input.
set(GSPH_FUZZ_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all
                         -fno-omit-frame-pointer)
add_compile_options(-fsanitize=fuzzer-no-link ${GSPH_FUZZ_SANITIZERS})
add_link_options(-fsanitize=address,undefined)
