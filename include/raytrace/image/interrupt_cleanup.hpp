// Removal of the temporary file being written when a signal ends the program (INT, TERM, HUP, QUIT, USR1, ALRM,
// PIPE, XCPU and the others whose default is to end it).
#pragma once

#include <string>

namespace rt {

// Registers the one temporary file to remove if one of those signals arrives, and installs the handlers where
// they are not in place. A handler unlinks the file, then lets the signal end the program by its default action (the
// shell sees 130, 143 or 129). A signal the process ignores (as under nohup) stays ignored. Register the path
// before creating the file and clear it only once the file is renamed or removed: a signal in between then
// finds either the file or nothing at that random name, on whichever thread it is delivered.
void registerTemporary(const std::string& path);
void clearTemporary();

}  // namespace rt
