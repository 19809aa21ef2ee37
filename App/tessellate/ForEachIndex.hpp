#pragma once

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace nurbslod {

// body(i) for every i in [0, count): in order on the calling thread where `threads` is 1, in
// parallel (oneTBB) on at most `threads` threads otherwise (0: all cores). Each call must write
// only its own results; the results then do not depend on the thread count.
template <class Index, class Body>
void forEachIndex(Index count, int threads, const Body& body) {
    if (threads == 1) {
        for (Index i = 0; i < count; ++i) body(i);
        return;
    }
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] { tbb::parallel_for(Index(0), count, body); });
}

}  // namespace nurbslod
