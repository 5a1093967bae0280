#include "acd/internal/shortest_paths.h"
