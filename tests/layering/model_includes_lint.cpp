// Compiled as if it were a file of model/ (with model/'s view of the tree, cmake/rooms.cmake) by ctest
// `layering-upward-include`, which passes only when the include of lint/ below is not found: a room cannot
// include a room above it. The first include, of a room below, must be found.
#include "text/source_map.hpp"
#include "lint/config.hpp"
