// The racket baseline's entry in the scripted registry (scripted_policy.cpp), kept beside
// scripted_racket.cpp so that the registry needs no header of it.
#include "scripted_racket.h"

namespace olympics::client {

std::unique_ptr<Policy> make_scripted_racket() { return std::make_unique<ScriptedRacketPolicy>(); }

}  // namespace olympics::client
