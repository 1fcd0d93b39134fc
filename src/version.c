/* SPDX-License-Identifier: MIT */
#include "agjk/base.h"

int agjk_version(void) { return AGJK_VERSION_NUMBER; }

const char *agjk_version_string(void) { return AGJK_VERSION_STRING; }
