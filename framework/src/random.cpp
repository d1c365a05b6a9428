#include "raylab/random.h"

// Pcg32 is defined inline in its header, so that the samplers' loops inline its step.
