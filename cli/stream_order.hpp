// Output and messages in the order they were written when both streams go to one pipe or file
// (`sphdeck ... 2>&1 | less`, a CI log): stdout is otherwise block-buffered there and its lines land
// after stderr's.
#pragma once

namespace sphdeck::cli {

// Makes stdout line-buffered when it and stderr are the same pipe or file; leaves a terminal (already
// line-buffered) and separate destinations (full buffering, fast for big reports) as they are.
void keep_streams_in_order();

}  // namespace sphdeck::cli
