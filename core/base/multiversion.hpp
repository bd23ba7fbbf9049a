#pragma once

/// Marks a function whose body is dominated by error-free products (std::fma), or a hot
/// floating-point kernel: GCC emits a copy for processors with the fused multiply-add
/// instruction (and so AVX's three-operand encoding) and one for plain x86-64, and the
/// dynamic loader picks one at start (GNU ifunc). Without it the baseline x86-64 build
/// calls libm's fma for every product (a call that spills the live vector registers),
/// which makes compensated evaluation several times slower; the intersection search's
/// clipping step, pieces and Krawczyk test also run fewer instructions in their fma copies. `flatten` inlines
/// every callee into each copy: a helper left out of line would be compiled once, for plain x86-64,
/// and the fma copy would only call it. Both copies round every operation the same way (fma is
/// exact-then-rounded either way, and the build turns off contraction of a * b + c,
/// -ffp-contract=off in CMakeLists.txt), so results are bit for bit equal. Elsewhere, and under
/// clang (the fuzzing builds; it refuses `flatten` on clones), the macro is empty.
#if defined(__x86_64__) && defined(__linux__) && !defined(__FMA__) && defined(__GNUC__) && \
    !defined(__clang__)
#define BEZIER_FMA_CLONES __attribute__((target_clones("fma", "default"), flatten))
#else
#define BEZIER_FMA_CLONES
#endif
