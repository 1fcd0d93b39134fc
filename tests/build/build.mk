# tests/build: checks of the build and the installed packages.
#   same-sources.sh    make and meson build the same library sources
#   cmake-package.sh   the CMake package against a temporary install (skipped without cmake)
#   man-sync.sh        the agjk(1) man page lists exactly the options of agjk --help
CHECK_SCRIPTS += tests/build/same-sources.sh tests/build/cmake-package.sh tests/build/man-sync.sh
