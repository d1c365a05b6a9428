#pragma once
// <windows.h> for the few Windows-only lines (console, UI language, Job objects), without its min and
// max macros, which would break std::min, and without the rarely used parts of the API.
#ifdef _WIN32
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX // libstdc++ defines it (MinGW)
#define NOMINMAX
#endif
#include <windows.h>
#endif
