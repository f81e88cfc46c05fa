# Third-party libraries, all from Debian packages (tools/install-deps.sh installs them).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(MPI REQUIRED COMPONENTS C)
find_package(ZLIB REQUIRED) # CRC-32 of checkpoint files
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
# FFTW's MPI transforms (libfftw3-mpi-dev, no pkg-config file): the pressure solve on a grid
# split across ranks (linsolve/fft_mpi_poisson.hpp).
find_path(FFTW3_MPI_INCLUDE_DIR fftw3-mpi.h REQUIRED)
find_library(FFTW3_MPI_LIBRARY fftw3_mpi REQUIRED)

# hypre ships neither a CMake config nor a pkg-config file on Debian 12.
find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre REQUIRED)
find_library(HYPRE_LIBRARY HYPRE REQUIRED)
add_library(fddem_hypre INTERFACE)
target_include_directories(fddem_hypre SYSTEM INTERFACE ${HYPRE_INCLUDE_DIR})
target_link_libraries(fddem_hypre INTERFACE ${HYPRE_LIBRARY} MPI::MPI_C)

if(FDDEM_ENABLE_OPENMP)
    find_package(OpenMP REQUIRED COMPONENTS CXX)
    # FFTW's OpenMP build (libfftw3-dev ships it): the pressure transforms on all threads.
    find_library(FFTW3_OMP_LIBRARY fftw3_omp REQUIRED)
endif()
