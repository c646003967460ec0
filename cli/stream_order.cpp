#include "cli/stream_order.hpp"

#include <cstdio>
#include <sys/stat.h>

namespace sphdeck::cli {

void keep_streams_in_order() {
    struct stat out {
    }, err{};
    if (fstat(1, &out) != 0 || fstat(2, &err) != 0) return;
    if (out.st_dev == err.st_dev && out.st_ino == err.st_ino && !S_ISCHR(out.st_mode))
        std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
}

}  // namespace sphdeck::cli
