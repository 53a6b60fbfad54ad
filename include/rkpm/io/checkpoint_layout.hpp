#pragma once
// checkpoint_layout: how the arrays of one rank's part of a model (parallel/distributed_solver.hpp)
// map to the arrays of the whole model, so that a checkpoint written from P processes is the
// file one process writes, and any number of processes can read it (docs/method.md section 9.5).
// The writer (io/checkpoint_writer.hpp) asks the layout for the whole array of every section
// the layout names (each rank's owned values, gathered on the rank that writes the file); the
// reader (io/checkpoint_reader.hpp) takes each local value from the whole array by its index
// there. A checkpoint in parts (io/checkpoint_parts.hpp) is read through a layout too. Arrays
// the layout does not name (the time, the energies, the contact's per-slave
// state) are the same on every rank and written as they are. No MPI here: a backend implements
// it (parallel/distributed_checkpoint.hpp).

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm::io {

class checkpoint_layout {
 public:
  virtual ~checkpoint_layout() = default;
  // For a section of the whole model's particles or points: each local value's index in the
  // whole array; nullptr for a section every rank holds whole.
  virtual const std::vector<stored_index>* whole_index(std::string_view section) const = 0;
  // The whole array of `section` (bytes, value_bytes per value) from every rank's owned values,
  // on the rank that writes the file (empty on the others). Collective.
  virtual std::string gather(std::string_view section, std::span<const char> local, std::size_t value_bytes) = 0;
  // Whether this rank writes the file.
  virtual bool writes() const = 0;
  // For a checkpoint in parts (io/checkpoint_parts.hpp): puts the values of `section` at this
  // rank's indices (whole_index) into `local` from the parts' files and returns true; false for
  // a checkpoint in one file, whose reader takes them from its own bytes.
  virtual bool take_from_parts(std::string_view /*section*/, std::span<char> /*local*/,
                               std::size_t /*value_bytes*/) const {
    return false;
  }
};

}  // namespace rkpm::io
