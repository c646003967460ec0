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
# must be visible. Extra sources (a generated file) go after SOURCES. COLD names files (globs, relative to
# the room's folder) that run once a process or only on a broken deck: they compile apart, in a batch of
# their own at -O1 (sphdeck_<room>_cold, an object library whose objects the room's library holds), while
# the rest of the room keeps -O3 (issue 42: grammar/'s keyword tables). Everything above the rooms (cli/,
# tests, benchmarks, fuzz targets) links sphdeck_core, which sees the whole tree.

set(SPHDECK_ROOMS_VIEW ${PROJECT_BINARY_DIR}/rooms)

# The rooms are compiled position-independent, so that the Python module (python/), a shared object,
# can link them as the command line does. -fno-semantic-interposition lets the compiler inline and call
# the rooms' own functions directly, as in the executable's code, so the command line loses no speed.
include(CheckCXXCompilerFlag)
check_cxx_compiler_flag(-fno-semantic-interposition SPHDECK_HAS_NO_SEMANTIC_INTERPOSITION)

function(sphdeck_add_room room)
  cmake_parse_arguments(PARSE_ARGV 1 ROOM "" "" "DEPENDS;SOURCES;COLD")
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${room}/*.cpp)
  set(target sphdeck_${room})
  set(cold_sources "")
  foreach(pattern IN LISTS ROOM_COLD)
    file(GLOB matched CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${room}/${pattern})
    if(NOT matched)
      message(FATAL_ERROR "sphdeck_add_room(${room}): COLD ${pattern} matches no file")
    endif()
    list(APPEND cold_sources ${matched})
  endforeach()
  if(cold_sources)
    list(REMOVE_ITEM sources ${cold_sources})
  endif()
  add_library(${target} STATIC ${sources} ${ROOM_SOURCES})
  set(targets ${target})
  if(cold_sources)
    add_library(${target}_cold OBJECT ${cold_sources})
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:${target}_cold>)
    list(APPEND targets ${target}_cold)
  endif()
  set_target_properties(${targets} PROPERTIES POSITION_INDEPENDENT_CODE ON)

  # The room's view of the tree: links to itself and to the rooms it stands on.
  set(view ${SPHDECK_ROOMS_VIEW}/${room})
  file(MAKE_DIRECTORY ${view})
  foreach(visible ${room} ${ROOM_DEPENDS})
    if(NOT EXISTS ${view}/${visible})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${visible} ${view}/${visible} SYMBOLIC)
    endif()
  endforeach()
  set(below "")
  foreach(dependency ${ROOM_DEPENDS})
    list(APPEND below sphdeck_${dependency})
  endforeach()
  foreach(each IN LISTS targets)
    if(SPHDECK_HAS_NO_SEMANTIC_INTERPOSITION)
      target_compile_options(${each} PRIVATE -fno-semantic-interposition)
    endif()
    target_include_directories(${each} PRIVATE ${view})
    target_link_libraries(${each} PUBLIC ${below} taocpp::pegtl Eigen3::Eigen fmt::fmt
      nlohmann_json::nlohmann_json tomlplusplus::tomlplusplus OpenMP::OpenMP_CXX)
    target_compile_definitions(${each} PRIVATE SPHDECK_VERSION="${PROJECT_VERSION}")
  endforeach()
  set_property(GLOBAL APPEND PROPERTY SPHDECK_ROOM_TARGETS ${targets})
  if(cold_sources)
    sphdeck_optimise(${target}_cold -O1)  # cmake/speed_up.cmake
  endif()
endfunction()
