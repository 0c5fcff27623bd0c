#include "shim/Syscall.hpp"

#if !defined(__x86_64__)
#error "the shim's syscall stub is written for x86-64 (docs/shim.md: other machines)"
#endif

// System V x86-64: arguments in rdi, rsi, rdx, rcx, r8, r9, the 7th on the
// stack; the kernel takes the number in rax and arguments in rdi, rsi, rdx,
// r10, r8, r9.
asm(R"(
  .text
  .globl simswift_shim_syscall
  .hidden simswift_shim_syscall
  .type simswift_shim_syscall, @function
simswift_shim_syscall:
  movq %rdi, %rax
  movq %rsi, %rdi
  movq %rdx, %rsi
  movq %rcx, %rdx
  movq %r8, %r10
  movq %r9, %r8
  movq 8(%rsp), %r9
  syscall
  ret
  .size simswift_shim_syscall, .-simswift_shim_syscall
)");
