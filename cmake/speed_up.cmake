# Build speed, one call a target:
#   sphdeck_speed_up(<target> [HEADERS <header>...] [PCH_FROM <target>] [BATCH_SIZE <n>] [NO_PCH])
#
# A unity build compiles a target's sources in batches (one generated file that #includes up to 32 of
# them), so the standard library and the third-party headers are parsed, and their inline functions
# optimised, once a batch instead of once a file; a precompiled header (PCH) holds the headers nearly
# every file includes (HEADERS adds the target's own costly ones), parsed once a target. -ftime-trace on
# the heaviest units: two thirds of a unit's time is the optimiser on inline code from headers (CLI11 in
# each cli/cmd_*.cpp, nlohmann-json in the renderers and lsp/, fmt everywhere), which only batching
# shares; the header parse is the rest, which both share.
#
# Options: -DSPHDECK_UNITY_BUILD=OFF compiles file by file (quicker rebuilds while editing one file),
# -DSPHDECK_PCH=OFF leaves the precompiled headers out (then each file must include what it uses: build a
# tree that way now and then).
#
# Safety: a batch keeps whatever a file declares at namespace scope in sight of the files after it. A clash
# is a compile error at best; at worst a later file's unqualified name finds an earlier file's helper
# instead of a header's (rules_preview.cpp's file-local `max_listed = 20` once replaced particle_groups.hpp's
# 5 in rules_references.cpp). So the batches are formed here, at configure time, by
# scripts/check_unity_clashes.py --group: no file shares a batch with a file that spells one of its
# file-local names where that name would be found, and the users of CLI11 or nlohmann-json go side by
# side. The ctest `unity-clashes` checks the batches CMake wrote (a helper added since the last configure:
# re-run cmake, or rename the helper). A file that must never be batched goes in SPHDECK_UNITY_ALONE.
# Each test file keeps its code in a namespace named after it (`namespace test_config_cpp {`): its helpers,
# using-declarations and `using namespace` then lend nothing to the next file, and the 99 test files
# compile in 8 batches instead of 42 (each batch instantiates doctest's and nlohmann-json's templates
# again). A new test file does the same. The library's files keep the rule by name: a file-local helper
# is named for what it does in its file (`shown_json`, `evaluate_noh`, `trim_cell`), not with a word that
# another file of its room also uses for its own (`shown`, `evaluate`, `trim`), and a declaration two files
# share goes in a header: each room then compiles in as few batches as its size allows (issue 42: the
# program's 46 batches became 18 at 32 a batch, its compiles 19 % less CPU under the same load; then 15,
# one a room but lint/'s table of starter checks, at up to 64 a room: SPHDECK_ROOM_BATCH_SIZE below).
option(SPHDECK_UNITY_BUILD "Compile each target's sources in batches (cmake/speed_up.cmake)" ON)
option(SPHDECK_PCH "Precompiled headers for the standard and third-party headers (cmake/speed_up.cmake)" ON)
set(SPHDECK_UNITY_BATCH_SIZE 32 CACHE STRING "Sources per unity batch (cmake/speed_up.cmake)")
# A room (and cli/) in one batch where its clashes allow: the largest, grammar/, has 63 files. Each batch
# more of a room costs its fixed price again (issue 42, both compiled side by side under the same load:
# grammar's three batches 66.1 CPU s, one 58.0; model's two 47.3, one 44.0). The tests keep
# SPHDECK_UNITY_BATCH_SIZE: their batch of 32 files is already `make test`'s longest compile.
set(SPHDECK_ROOM_BATCH_SIZE 64 CACHE STRING "Sources per unity batch of a room and of cli/ (cmake/speed_up.cmake)")

# Files that compile alone, with why.
set(SPHDECK_UNITY_ALONE
  tests/main.cpp  # defines DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN before doctest.h: must come first, without the PCH
)
list(TRANSFORM SPHDECK_UNITY_ALONE PREPEND ${PROJECT_SOURCE_DIR}/)

# The headers that most of the project's files include (counted over the sources): in every PCH.
set(SPHDECK_PCH_COMMON
  <algorithm> <array> <cmath> <cstddef> <cstdint> <filesystem> <functional> <map> <memory> <optional>
  <set> <span> <string> <string_view> <vector> <fmt/format.h>)

# ccache caches compiles that use a PCH only when told that the PCH's macros and __TIME__ need no check
# (ccache manual, "Precompiled headers"); the setting travels with each compile, the user's ccache.conf
# stays as it is.
if(SPHDECK_PCH)
  get_filename_component(_sphdeck_launcher_name "${CMAKE_CXX_COMPILER_LAUNCHER}" NAME)
  if(_sphdeck_launcher_name STREQUAL "ccache")
    set(SPHDECK_PCH_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=pch_defines,time_macros
        ${CMAKE_CXX_COMPILER_LAUNCHER})
  endif()
endif()

# The batches of every target given to sphdeck_speed_up, formed by scripts/check_unity_clashes.py so that
# no file shares one with a file that spells one of its file-local names (in a namespace where the name
# would be found); called once, deferred to the end of the top-level CMakeLists.txt.
function(sphdeck_form_unity_batches)
  get_property(entries GLOBAL PROPERTY SPHDECK_UNITY_SOURCES)
  set(list_file ${PROJECT_BINARY_DIR}/unity_batch_sources.txt)
  string(REPLACE ";" "\n" text "${entries}")
  file(WRITE ${list_file} "${text}\n")
  set(status "no Python 3")
  if(Python3_FOUND)  # found by the top-level CMakeLists.txt
    execute_process(
      COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_unity_clashes.py
              --source ${PROJECT_SOURCE_DIR}
              --cache ${PROJECT_BINARY_DIR}/unity_batches_parsed.pickle --group-targets ${list_file}
      OUTPUT_VARIABLE batches RESULT_VARIABLE status)
  endif()
  if(NOT status EQUAL 0)
    message(WARNING "compiled file by file (scripts/check_unity_clashes.py: ${status})")
    return()
  endif()
  string(REPLACE "\n" ";" batches "${batches}")
  set(targets "")
  foreach(line IN LISTS batches)
    if(line MATCHES "^([^|]+)[|]([0-9]+)[|](.+)$")
      set_source_files_properties(${CMAKE_MATCH_3} TARGET_DIRECTORY ${CMAKE_MATCH_1}
        PROPERTIES UNITY_GROUP ${CMAKE_MATCH_1}_${CMAKE_MATCH_2})
      list(APPEND targets ${CMAKE_MATCH_1})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES targets)
  set_target_properties(${targets} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
endfunction()

function(sphdeck_speed_up target)
  cmake_parse_arguments(ARG "NO_PCH" "PCH_FROM;BATCH_SIZE" "HEADERS" ${ARGN})
  if(NOT ARG_BATCH_SIZE)
    set(ARG_BATCH_SIZE ${SPHDECK_UNITY_BATCH_SIZE})
  endif()
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  # Files with compile options of their own (the SIMD units, -ffp-contract=off) already stay out of
  # batches (CMake); they stay out of the PCH too, which was built with the target's options.
  set(own_options "")
  foreach(src IN LISTS sources)
    get_filename_component(path ${src} ABSOLUTE BASE_DIR ${source_dir})
    get_source_file_property(options ${path} TARGET_DIRECTORY ${target} COMPILE_OPTIONS)
    if(options OR path IN_LIST SPHDECK_UNITY_ALONE)
      list(APPEND own_options ${path})
    endif()
  endforeach()
  if(own_options)
    set_source_files_properties(${own_options} TARGET_DIRECTORY ${target}
      PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON SKIP_PRECOMPILE_HEADERS ON)
  endif()
  if(SPHDECK_UNITY_BUILD)
    set(batched "")
    foreach(src IN LISTS sources)
      get_filename_component(path ${src} ABSOLUTE BASE_DIR ${source_dir})
      if(path MATCHES "\\.cpp$" AND NOT path IN_LIST own_options)
        list(APPEND batched ${path})
      endif()
    endforeach()
    # Formed for every target at once, at the end of the configure (one Python run, not one a target:
    # each run parsed the project's headers again, a third of a fresh configure).
    foreach(path IN LISTS batched)
      set_property(GLOBAL APPEND PROPERTY SPHDECK_UNITY_SOURCES "${target}|${ARG_BATCH_SIZE}|${path}")
    endforeach()
    get_property(deferred GLOBAL PROPERTY SPHDECK_UNITY_DEFERRED)
    if(NOT deferred)
      set_property(GLOBAL PROPERTY SPHDECK_UNITY_DEFERRED ON)
      cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL sphdeck_form_unity_batches)
    endif()
    # GCC 12 at -O3 inlines std::string copies deeper in a batch and then reports bounds it cannot
    # know (GCC bugs 105329, 105651): false -Warray-bounds and -Wstringop-overflow in <string>.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread)
    endif()
  endif()
  # NO_PCH: a target of one batch gains nothing from a PCH (it would parse the headers once either way)
  # and would pay the PCH's own compile.
  if(SPHDECK_PCH AND NOT ARG_NO_PCH)
    if(ARG_PCH_FROM)
      # Several small libraries with the same compile options can share one PCH (some 7 CPU seconds
      # each to build); a mismatch is an error (-Winvalid-pch with -Werror), not a silent slow-down.
      target_precompile_headers(${target} REUSE_FROM ${ARG_PCH_FROM})
    else()
      target_precompile_headers(${target} PRIVATE ${SPHDECK_PCH_COMMON} ${ARG_HEADERS})
    endif()
    if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
      # No build time in the PCH, so that ccache can reuse what uses it (ccache manual).
      target_compile_options(${target} PRIVATE "SHELL:-Xclang -fno-pch-timestamp")
    endif()
    if(SPHDECK_PCH_LAUNCHER)
      set_target_properties(${target} PROPERTIES CXX_COMPILER_LAUNCHER "${SPHDECK_PCH_LAUNCHER}")
    endif()
  endif()
endfunction()

# A lighter optimisation level for code no user waits on (issue 42): the test code at -O0
# (CMakeLists.txt), the command line's option handling (cli/), the MCP server, the verification cases,
# the findings' renderers (diag/), the engine's orchestration (engine/) and the Python module at -O1;
# the rooms that read, check, preview and solve keep the build type's -O3. Measured a batch at a time: four test files 27.1 CPU s at
# -O3, 17.3 at -O1; the command line's larger batch (CLI11's templates) 55.4 at -O3, 48.8 at -O2, 42.5 at
# -O1; the MCP room 27.0, 24.8, 17.8. -O2 saves little (most of a batch's time is instantiating the
# headers' templates, which the level does not change), so what users wait on keeps -O3. -O2 and -O1 can
# reuse a PCH built at -O3 (GCC compares macros, and __OPTIMIZE__ is the same); -Os and -O0 could not.
# Release builds only (the sanitizer trees keep -O0). -DSPHDECK_LIGHT_OPTIMISATION=OFF: everything at -O3.
option(SPHDECK_LIGHT_OPTIMISATION "Compile code no user waits on at -O1 in Release builds (cmake/speed_up.cmake)" ON)
function(sphdeck_optimise target level)
  if(SPHDECK_LIGHT_OPTIMISATION)
    # After the build type's -O3 on the command line, so this one counts.
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:${level}>)
  endif()
endfunction()
