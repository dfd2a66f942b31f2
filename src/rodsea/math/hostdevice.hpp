#pragma once
// RODSEA_HD marks a function that both executors compile: the CPU backend's loops and, under
// nvcc, the CUDA kernels call the same code (HOOMD-blue's HOSTDEVICE). Empty on the host compiler.
// Such functions use only other RODSEA_HD functions, <cmath> and plain values: no allocation,
// no exceptions, no std containers.
#if defined(__CUDACC__)
#define RODSEA_HD __host__ __device__
#else
#define RODSEA_HD
#endif
