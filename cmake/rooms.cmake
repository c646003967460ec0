# One static library per room (docs/architecture.md, "Rooms as the build links them"): sphdeck_<room> is
# built from <room>/*.cpp (its subfolders too) and links the rooms it stands on, so the linker sees them in
# order. What a room may include is what it can see: its files compile with the include path
# ${PROJECT_BINARY_DIR}/rooms/<room>/, a folder of links to its own folder and to the rooms below it, and
# nothing else of the tree. An `#include "lint/..."` written in model/ then fails to compile ("No such file"),
# and ctest `layering-upward-include` proves that it does.
#
#   sphdeck_add_room(model DEPENDS grammar diag text)
#
# DEPENDS names every room below, not just the next one: a room may include any room under it, and each
# must be visible. Extra sources (a generated file) go after SOURCES. Everything above the rooms (cli/,
# tests, benchmarks, fuzz targets) links sphdeck_core, which sees the whole tree.

set(SPHDECK_ROOMS_VIEW ${PROJECT_BINARY_DIR}/rooms)

# The rooms are compiled position-independent, so that the Python module (python/), a shared object,
# can link them as the command line does. -fno-semantic-interposition lets the compiler inline and call
# the rooms' own functions directly, as in the executable's code, so the command line loses no speed.
include(CheckCXXCompilerFlag)
check_cxx_compiler_flag(-fno-semantic-interposition SPHDECK_HAS_NO_SEMANTIC_INTERPOSITION)

function(sphdeck_add_room room)
  cmake_parse_arguments(PARSE_ARGV 1 ROOM "" "" "DEPENDS;SOURCES")
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${room}/*.cpp)
  set(target sphdeck_${room})
  add_library(${target} STATIC ${sources} ${ROOM_SOURCES})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  if(SPHDECK_HAS_NO_SEMANTIC_INTERPOSITION)
    target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  endif()

  # The room's view of the tree: links to itself and to the rooms it stands on.
  set(view ${SPHDECK_ROOMS_VIEW}/${room})
  file(MAKE_DIRECTORY ${view})
  foreach(visible ${room} ${ROOM_DEPENDS})
    if(NOT EXISTS ${view}/${visible})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${visible} ${view}/${visible} SYMBOLIC)
    endif()
  endforeach()
  target_include_directories(${target} PRIVATE ${view})

  set(below "")
  foreach(dependency ${ROOM_DEPENDS})
    list(APPEND below sphdeck_${dependency})
  endforeach()
  target_link_libraries(${target} PUBLIC ${below} taocpp::pegtl Eigen3::Eigen fmt::fmt nlohmann_json::nlohmann_json
    tomlplusplus::tomlplusplus OpenMP::OpenMP_CXX)
  target_compile_definitions(${target} PRIVATE SPHDECK_VERSION="${PROJECT_VERSION}")
  set_property(GLOBAL APPEND PROPERTY SPHDECK_ROOM_TARGETS ${target})
endfunction()
