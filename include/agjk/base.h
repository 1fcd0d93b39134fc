/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/base.h
 * @brief Export macro, version macros and run-time version query.
 *
 * @defgroup agjk_base Base
 * Everything the other agjk headers build on. Nothing here depends on a build
 * macro chosen by the caller: the ABI is the same whatever the user defines.
 * @{
 */
#ifndef AGJK_BASE_H
#define AGJK_BASE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Marks a function exported from the shared library. The library is built
 *  with -fvisibility=hidden; only symbols marked here are visible. */
#if defined(_WIN32) && defined(AGJK_BUILDING_SHARED)
#define AGJK_API __declspec(dllexport)
#elif defined(_WIN32) && defined(AGJK_USING_SHARED)
#define AGJK_API __declspec(dllimport)
#elif defined(__GNUC__) || defined(__clang__)
#define AGJK_API __attribute__((visibility("default")))
#else
#define AGJK_API
#endif

/** Major version: bumped on any ABI break; equals the shared library's SOVERSION. */
#define AGJK_VERSION_MAJOR 0
/** Minor version: bumped when functions or appended fields are added. */
#define AGJK_VERSION_MINOR 2
/** Patch version: bumped for fixes that change no interface. */
#define AGJK_VERSION_PATCH 0
/** The version as one integer, 10000 * major + 100 * minor + patch. */
#define AGJK_VERSION_NUMBER \
    (AGJK_VERSION_MAJOR * 10000 + AGJK_VERSION_MINOR * 100 + AGJK_VERSION_PATCH)
/** The version as a string literal, "major.minor.patch". */
#define AGJK_VERSION_STRING "0.2.0"

/** Version of the library linked at run time, as AGJK_VERSION_NUMBER encodes it.
 *  Compare with AGJK_VERSION_NUMBER to detect a header/library mismatch. */
AGJK_API int agjk_version(void);

/** Version of the library linked at run time as a static string "major.minor.patch". */
AGJK_API const char *agjk_version_string(void);

#ifdef __cplusplus
}
#endif

#endif /* AGJK_BASE_H */
/** @} */
