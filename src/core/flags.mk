# flags.mk -- compiler settings shared by the core and the programs built on it (tools/program.mk).
#   SAN=1: address + undefined sanitizers, objects and libraries in build-san/ (the tests use it)
SAN     ?= 0
ifeq ($(SAN),1)
CORE_BUILD := build-san
OPT     := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
else
CORE_BUILD := build
OPT     := -O2 -g
endif
CFLAGS  += -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic $(OPT)
