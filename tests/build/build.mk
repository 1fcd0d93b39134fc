CHECK_SCRIPTS += tests/build/same-sources.sh
