#pragma once
// How many threads fit in the address space the process may still take.
//
// A thread's stack is reserved whole when the thread starts (8 MB under Linux's usual stack
// limit). Under an address-space cap (--max-memory-mb, `ulimit -v`), a pool that starts threads
// until one fails leaves nothing for the work the threads were started to do, and that work then
// fails for want of memory. So a pool asks first how many threads fit in half the headroom, and
// keeps the other half for the work.

namespace polyplan {

// `asked`, or fewer when the address-space limit's headroom (the limit less what the process
// already takes) holds fewer than twice that many thread stacks; at least 1 (the caller's thread).
unsigned threads_within_memory(unsigned asked);

}  // namespace polyplan
