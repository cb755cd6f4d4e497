#ifndef phasefield_core_block_vector_tools_h
#define phasefield_core_block_vector_tools_h

#include <phasefield/core/linear_algebra.h>
#include <vector>

namespace PhaseField
{
  /**
   * Move the blocks @p blocks of @p fields, in this order, into a block
   * vector of their own (no entry is copied; those blocks of @p fields are
   * left empty), e.g. to transfer them to another mesh while the others
   * are freed or restored there. swap_into() puts them back.
   */
  BlockVector
  take_blocks(BlockVector &fields, const std::vector<unsigned int> &blocks);

  /**
   * Swap block i of @p part with block @p blocks[i] of @p fields (the
   * blocks of a checkpoint or of a transfer back into the state).
   */
  void
  swap_into(const std::vector<unsigned int> &blocks,
            BlockVector                     &part,
            BlockVector                     &fields);
} // namespace PhaseField

#endif
