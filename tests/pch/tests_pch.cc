// Translation unit of the target that builds the precompiled tests.h
// (tests/CMakeLists.txt); every test executable reuses that header.
#include "tests.h"
