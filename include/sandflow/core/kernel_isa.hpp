#pragma once
// The lattice's hot loops are built for several x86-64 instruction sets, and
// the widest one the processor has is chosen when the program loads (GCC
// function multiversioning): one binary runs everywhere and uses AVX where it
// exists. FMA contraction is off project-wide (CMakeLists.txt), so every
// version rounds each operation alike: the populations do not depend on which
// version ran, only reductions over lanes (the mass sum) may differ in the
// last bit.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SF_KERNEL_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SF_KERNEL_CLONES
#endif
