#include <benchmark/benchmark.h>

#include "snaxels/util/memory.h"

// The benchmarks run with the allocator the programs use (tune_allocator).
int main(int argc, char** argv) {
    snaxels::tune_allocator();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
