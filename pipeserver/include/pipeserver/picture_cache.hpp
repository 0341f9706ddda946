// How much decoded picture a pipeserver's image cache may hold (--picture-cache-mb, on
// `pipeserver` and `l2wall run` alike), and the default sized for the machine: a picture far
// larger than memory is shown through this much, whatever its size.
#pragma once

namespace l2 {

// A sixteenth of the machine's physical memory shared among the `pipeservers` it runs, and never
// less than kDefaultPictureCacheMegabytes (image/picture_regions.hpp: what a picture stored as
// scanlines took to be held whole, decoded once, before the limit could be set). Pure.
double default_picture_cache_mb(double physical_mb, int pipeservers);

// This machine's physical memory in MiB (sysconf); 0 when it does not say.
double physical_memory_mb();

}  // namespace l2
