# tests/build: checks of the build and the installed packages.
#   same-sources.sh    make and meson build the same library sources
#   cmake-package.sh   the CMake package against a temporary install (skipped without cmake)
#   man-sync.sh        agjk(1) names exactly the options and output keys of agjk,
#                      README.md's sample session prints what agjk prints,
#                      agjk(3) every public header
CHECK_SCRIPTS += tests/build/same-sources.sh tests/build/cmake-package.sh tests/build/man-sync.sh
