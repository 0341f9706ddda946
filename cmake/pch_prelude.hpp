// The first header of the project's precompiled headers (Targets.cmake).
//
// In unoptimised builds fmt's core.h wraps itself in `#pragma GCC optimize("Og")`. With that
// restored from a precompiled header, GCC 12 made the SSE intrinsics headers included after it
// take their __OPTIMIZE__ forms, whose shift counts must be constants, and
// pipeserver/src/scan_out.cpp stopped compiling in the debug preset ("the last argument must
// be an 8-bit immediate"; reproduced with a PCH of <fmt/format.h> alone, -O0, _mm_slli_si128).
// fmt's own switch leaves the pragmas out.
#pragma once
#define FMT_GCC_PRAGMA(arg)
