# Warning, ISA and sanitizer flags shared by every target of the build.
add_library(mcd_flags INTERFACE)
# No errno from math functions and no FP traps (never read or enabled): lets
# GCC vectorise loops with sqrt and float selects; results stay IEEE-exact.
target_compile_options(mcd_flags INTERFACE -Wall -Wextra -ffp-contract=off -fno-math-errno
                                           -fno-trapping-math)
if(MCD_WERROR)
  target_compile_options(mcd_flags INTERFACE -Werror)
endif()
if(MCD_ARCH)
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag("-march=${MCD_ARCH}" MCD_HAS_MARCH)
  if(MCD_HAS_MARCH)
    add_compile_options(-march=${MCD_ARCH})
  endif()
endif()
if(MCD_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  # The median kernel's selection networks are fold expressions of up to
  # ~1000 compare-exchanges; clang's default nesting limit is 256.
  add_compile_options(-fbracket-depth=1024)
endif()
if(MCD_BUILD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MCD_BUILD_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
