set(PLISSE_IO_OUTPUT_SOURCES atomic_file.cpp)
