#pragma once
// Keeping a command's outputs apart from its inputs and from each other. Every command lists the
// files it will write and the files it reads before it writes anything; an output that is the
// same file as an input (a record named like a recorder's CSV, `spectrum --csv` onto its record)
// or as another output is refused as bad input, naming the option or JSON field that chose it.
#include <string>
#include <vector>

namespace pound::io {

// A file and what chose its name, for messages: "--out", "/recorders/0/file", "the model"; for
// a field of a file, that file (an error about the output names it as its file).
struct NamedPath {
  std::string path;
  std::string named_by;
  std::string in_file = "";
};

// Throws InputError when an output is the same file as an input or as an earlier output: the
// same inode when both exist, else the same absolute path once symlinks and "." / ".." are
// resolved.
void check_outputs_apart(const std::vector<NamedPath>& inputs,
                         const std::vector<NamedPath>& outputs);

// `path` absolute, with symlinks of its existing part resolved and "." and ".." folded: one
// spelling of a file however it was typed ("sets/a.json", "./sets/a.json", "/work/sets/a.json").
std::string resolved_path(const std::string& path);

// The default output folder of a command run on `input`: <parent>/<input's stem>. Throws
// InputError naming `option` when the stem cannot name a folder ("...json" has stem "..").
std::string folder_named_after(const std::string& parent, const std::string& input,
                               const std::string& option);

}  // namespace pound::io
