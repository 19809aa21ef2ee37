#include "occ/ModelImporter.hpp"
