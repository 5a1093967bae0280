#include "acd/poly_reader.h"
