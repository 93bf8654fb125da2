#pragma once
// Temporaries that a SIGINT, SIGTERM, SIGHUP or SIGXFSZ must not leave behind: the handler unlinks every
// registered path (async-signal-safe: fixed slots, unlink only), then hands the signal to the
// disposition it replaced (by default: the process ends). An ignored signal stays ignored.
namespace kdpm {

// Returns a slot for unregister_temporary, or -1 when every slot is taken (the temporary then
// simply is not removed on a signal).
int register_temporary(const char* path);
void unregister_temporary(int slot);

// Unlinks every registered temporary; async-signal-safe, for handlers of fatal signals.
void remove_registered_temporaries();

}  // namespace kdpm
