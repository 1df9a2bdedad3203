// C ABI around the Verilated mpdcc_core in pl_top's configuration (II > 1:
// explorers with shared search lanes; model Vmpdcc_core_shared, the same
// ports as Vmpdcc_core): mpdcc_core_shim.cpp compiled once more with the
// model's class and the C functions renamed (mks_new, mks_decide, mks_free).
#include "Vmpdcc_core_shared.h"
// mpdcc_core_ports.h includes Vmpdcc_core.h: the other model's header is
// not wanted here (its class name is mapped to this model's below).
#define VERILATED_VMPDCC_CORE_H_
#define Vmpdcc_core Vmpdcc_core_shared
#define MkSim MksSim
#define mk_new mks_new
#define mk_decide mks_decide
#define mk_free mks_free
#include "mpdcc_core_shim.cpp"
