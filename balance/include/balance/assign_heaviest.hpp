// The seed paper's assignment strategy: the heaviest tile of the next frame goes to the
// pipeserver that finishes first, i.e. tiles in decreasing estimated cost, each to the
// pipeserver with the least work so far.
#pragma once

#include <vector>

namespace l2 {

// The pipeserver (0..pipeservers-1) of each tile. Ties go to the pipeserver with fewer tiles,
// then the lower number, so tiles that cost nothing still reach every pipeserver (each needs
// a tile to earn READY). Equal costs keep their order.
std::vector<int> assign_heaviest_first(const std::vector<double>& cost, int pipeservers);

}  // namespace l2
