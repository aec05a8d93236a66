// The programs' memory allocator is jemalloc (Evans, "A scalable concurrent malloc(3)
// implementation for FreeBSD", BSDCan 2006), linked in place of the C library's, with its
// memory advised for transparent huge pages. A DDA step's arrays are megabytes each (the
// factor's blocks, the springs, the contacts), and on a virtual machine every fresh 4 KiB page
// costs a fault of some 10 µs on first touch: a 1,601-block wall's first step touches some
// 30 MB. On huge pages that is one fault per 2 MiB, and jemalloc packs arrays of every size
// into them and reuses freed memory rather than handing it back to the kernel, where the C
// library rounds each large array to its own pages (docs/studies/dda_step.md, "Memory:").
//
// jemalloc reads its options from the string `malloc_conf` of the program (jemalloc(3),
// "TUNING"); the environment variable MALLOC_CONF still overrides them. This file is compiled
// into each program that links the hydrodda library.

#include <jemalloc/jemalloc.h>

// thp:always    every mapping of user memory advised MADV_HUGEPAGE;
// metadata_thp  the allocator's own bookkeeping likewise;
// narenas:1     one arena for every thread (the small allocations still go through each
//               thread's cache): memory one thread frees (the second half of a clip)
//               serves the next large allocation of any thread, instead of
//               waiting in that thread's arena to be returned. The 10,200-block seal's peak
//               resident memory falls by about 30 MB, its run time unchanged.
// Where the kernel keeps huge pages off the advice is ignored and ordinary pages are used.
const char* malloc_conf = "thp:always,metadata_thp:always,narenas:1";
