// The binary traversal's stack kept out of local memory: its top four entries in registers
// (an ivec4 shifted on push and pop), the rest in this invocation's slice of a workgroup
// shared array, interleaved (entry k of invocation i at k * TRACE_WG_SIZE + i) so that lanes
// at the same depth touch different banks. Included by traverse.glsl when
// TRAVERSE_SHORT_STACK is defined: only the trace kernels do (local_size_x = TRACE_WG_SIZE).
// The integrators keep the local-memory stack.
//
// The register window always holds the top min(depth, 4) entries and the sentinel below
// them, so popping an empty stack yields TRAVERSAL_SENTINEL as the local stack does.

const uint SHORT_STACK_REGISTERS = 4u;
shared int short_stack_spill[(TRAVERSAL_STACK_SIZE - SHORT_STACK_REGISTERS) * TRACE_WG_SIZE];

ivec4 short_stack_top;
uint short_stack_depth;

void short_stack_push(int x) {
    if (short_stack_depth >= SHORT_STACK_REGISTERS) {
        short_stack_spill[(short_stack_depth - SHORT_STACK_REGISTERS) * TRACE_WG_SIZE + gl_LocalInvocationIndex] = short_stack_top.w;
    }
    short_stack_top = ivec4(x, short_stack_top.xyz);
    short_stack_depth++;
}

int short_stack_pop() {
    int x = short_stack_top.x;
    int refill = int(TRAVERSAL_SENTINEL);
    if (short_stack_depth > SHORT_STACK_REGISTERS) {
        refill = short_stack_spill[(short_stack_depth - SHORT_STACK_REGISTERS - 1u) * TRACE_WG_SIZE + gl_LocalInvocationIndex];
    }
    short_stack_top = ivec4(short_stack_top.yzw, refill);
    short_stack_depth = short_stack_depth > 0u ? short_stack_depth - 1u : 0u;
    return x;
}

#define TRAVERSAL_STACK_INIT()                                                                     \
    short_stack_top = ivec4(int(TRAVERSAL_SENTINEL));                                              \
    short_stack_depth = 0u
// No distances here: nothing is skipped (see the local stack in traverse.glsl).
#define TRAVERSAL_STACK_PUSH(x, t_bits) short_stack_push(x)
#define TRAVERSAL_STACK_POP(dst, cull) dst = short_stack_pop()
#define TRAVERSAL_STACK_TOP() ivec2(short_stack_top.x, 0)
#define TRAVERSAL_STACK_DROP_IF(c)                                                                 \
    if (c) {                                                                                       \
        short_stack_pop();                                                                         \
    }
