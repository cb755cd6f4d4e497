#include <phasefield/core/block_vector_tools.h>

namespace PhaseField
{
  BlockVector
  take_blocks(BlockVector &fields, const std::vector<unsigned int> &blocks)
  {
    BlockVector part(blocks.size());
    swap_into(blocks, part, fields);
    part.collect_sizes();
    return part;
  }



  void
  swap_into(const std::vector<unsigned int> &blocks,
            BlockVector                     &part,
            BlockVector                     &fields)
  {
    for (unsigned int i = 0; i < blocks.size(); ++i)
      fields.block(blocks[i]).swap(part.block(i));
    fields.collect_sizes();
  }
} // namespace PhaseField
