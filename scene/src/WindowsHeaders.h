#pragma once
// <windows.h> without its min/max macros and its rarely used APIs, for the
// files that lock, signal or probe processes; nothing on other systems.
#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#endif
