# program.mk -- build one C program against the core: the benchmark, the particleDistribution
# tutorial, the unit tests. Set these, then `include $(CORE)/tools/program.mk`:
#   CORE     the path of src/core
#   PROGRAM  the executable to make (may use $(CORE_BUILD): build or build-san)
#   SOURCES  its C files;  DEPS  other files it depends on (its own headers)
# `make SAN=1` builds program and core with the sanitizers.
include $(CORE)/flags.mk
CORE_LIBS := $(CORE)/$(CORE_BUILD)/libboxmesh.a $(CORE)/$(CORE_BUILD)/libcoarsedem.a

$(PROGRAM): $(SOURCES) $(DEPS) $(CORE)/coarse_dem.h $(CORE)/tools/box_mesh.h $(CORE_LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $(SOURCES) $(CORE_LIBS) -lm

# The core's own Makefile knows when its libraries are out of date.
$(CORE_LIBS): FORCE
	$(MAKE) -C $(CORE) SAN=$(SAN)

FORCE:
.PHONY: FORCE
