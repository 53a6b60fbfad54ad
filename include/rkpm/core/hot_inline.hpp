#pragma once
// RKPM_HOT_INLINE: inline this function into its caller whatever the compiler's size estimate
// says. For the few functions the force loop calls once per point per step (the material
// update), where GCC's heuristics keep a large body out of line and the call then passes its
// results through memory (Johnson-Cook's update, whose many exits make GCC outline it).
#if defined(__GNUC__) || defined(__clang__)
#define RKPM_HOT_INLINE [[gnu::always_inline]] inline
#else
#define RKPM_HOT_INLINE inline
#endif
