#pragma once
// Checkpoints (docs/method.md section 9.5): the format (io/checkpoint_format.hpp), the writer and
// the reader. Each stateful class writes its sections through save(checkpoint_writer&) const and
// reads them through load(checkpoint_reader&); both call one member template
// sections(archive, self), since writer and reader share the calls array(name, v),
// value(name, x) and part(p), so the order of the sections cannot differ between writing and
// reading.

#include <rkpm/io/checkpoint_format.hpp>
#include <rkpm/io/checkpoint_reader.hpp>
#include <rkpm/io/checkpoint_writer.hpp>
