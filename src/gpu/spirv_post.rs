//! SPIR-V that shaderc's optimiser left as glslang wrote it, optimised after all (a step of
//! build.rs, which includes this file; its tests run with the library's).
//!
//! SPIRV-Tools releases before v2023.4 skip their load/store-to-register and dead-code passes
//! on any module that declares an extension missing from the passes' allow lists, and
//! `SPV_EXT_shader_atomic_float_add` joined those lists only in SPIRV-Tools pull request #5348
//! (July 2023). Debian 12 ships SPIRV-Tools 2023.1, which scripts/setup.sh links, so BDPT's light
//! kernels and the shadow queue's splat kernels (the float atomics that add into the film) reached
//! the driver unoptimised: 400 to 6,500 Function-scope variables each, where every other kernel
//! keeps at most 39 (traversal stacks, arrays indexed at run time), and nearly twice the size.
//! lavapipe built `bdpt_light_cwbvh`'s pipeline in 93-106 ms from them, 63-71 ms once optimised.
//!
//! build.rs takes the extension and its capabilities out of such a module ([`hide_extension`]),
//! runs `spirv-opt -O` (the same SPIRV-Tools package) on what is left, and puts them back
//! ([`restore_extension`]). The passes do not look at the atomics' opcode, only at the list of
//! extensions, so the module optimised this way is the one a newer SPIRV-Tools makes.

/// The extension that stops SPIRV-Tools 2023.1's passes.
pub const FLOAT_ATOMIC_EXTENSION: &str = "SPV_EXT_shader_atomic_float_add";
/// Its capabilities (SPIR-V spec, "Capability"): AtomicFloat32AddEXT, AtomicFloat64AddEXT.
const FLOAT_ATOMIC_CAPABILITIES: [u32; 2] = [6033, 6034];
/// A module with more Function-scope variables than this was not optimised (see the top).
pub const UNOPTIMISED_FUNCTION_VARIABLES: usize = 100;

const HEADER_WORDS: usize = 5;
const OP_EXTENSION: u32 = 10;
const OP_CAPABILITY: u32 = 17;
const OP_VARIABLE: u32 = 59;
const STORAGE_FUNCTION: u32 = 7;

/// The module's instructions after the header: (opcode, the words after the opcode word).
fn instructions(words: &[u32]) -> impl Iterator<Item = (usize, u32, &[u32])> {
    let mut i = HEADER_WORDS.min(words.len());
    std::iter::from_fn(move || {
        let count = (*words.get(i)? >> 16) as usize;
        if count == 0 || i + count > words.len() {
            return None; // malformed: shaderc's output never is
        }
        let at = i;
        i += count;
        Some((at, words[at] & 0xffff, &words[at + 1..at + count]))
    })
}

/// The literal string `s` as SPIR-V words: UTF-8, nul-terminated, padded with nuls to a word.
fn string_words(s: &str) -> Vec<u32> {
    let mut bytes = s.as_bytes().to_vec();
    bytes.resize(s.len() / 4 * 4 + 4, 0);
    bytes.chunks(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
}

/// Whether the module declares `OpExtension "name"`.
pub fn declares_extension(words: &[u32], name: &str) -> bool {
    let want = string_words(name);
    instructions(words).any(|(_, op, args)| op == OP_EXTENSION && args == want.as_slice())
}

/// How many Function-scope variables (OpVariable ... Function) the module keeps.
pub fn function_variables(words: &[u32]) -> usize {
    instructions(words).filter(|(_, op, args)| *op == OP_VARIABLE && args.get(2) == Some(&STORAGE_FUNCTION)).count()
}

/// Whether build.rs should optimise the module again: it declares the float atomics and was
/// left unoptimised.
pub fn needs_reoptimising(words: &[u32]) -> bool {
    declares_extension(words, FLOAT_ATOMIC_EXTENSION) && function_variables(words) > UNOPTIMISED_FUNCTION_VARIABLES
}

/// The module without `OpExtension "SPV_EXT_shader_atomic_float_add"` and its capabilities,
/// and the capabilities it declared (for [`restore_extension`]).
pub fn hide_extension(words: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let ext = string_words(FLOAT_ATOMIC_EXTENSION);
    let mut caps = Vec::new();
    let mut drop = Vec::new();
    for (at, op, args) in instructions(words) {
        if op == OP_CAPABILITY && FLOAT_ATOMIC_CAPABILITIES.contains(&args[0]) {
            caps.push(args[0]);
            drop.push(at..at + 1 + args.len());
        } else if op == OP_EXTENSION && args == ext.as_slice() {
            drop.push(at..at + 1 + args.len());
        }
    }
    let mut out = Vec::with_capacity(words.len());
    let mut from = 0;
    for r in drop {
        out.extend_from_slice(&words[from..r.start]);
        from = r.end;
    }
    out.extend_from_slice(&words[from..]);
    (out, caps)
}

/// The module with `caps` declared again (first among the capabilities) and the extension
/// after the last capability, where the SPIR-V spec's logical layout puts extensions.
pub fn restore_extension(words: &[u32], caps: &[u32]) -> Vec<u32> {
    let ext = string_words(FLOAT_ATOMIC_EXTENSION);
    let after_caps = instructions(words).find(|(_, op, _)| *op != OP_CAPABILITY).map_or(words.len(), |(at, _, _)| at);
    let head = HEADER_WORDS.min(words.len());
    let mut out = Vec::with_capacity(words.len() + 2 * caps.len() + ext.len() + 1);
    out.extend_from_slice(&words[..head]);
    for &c in caps {
        out.extend_from_slice(&[(2 << 16) | OP_CAPABILITY, c]);
    }
    out.extend_from_slice(&words[head..after_caps]);
    out.push(((1 + ext.len() as u32) << 16) | OP_EXTENSION);
    out.extend_from_slice(&ext);
    out.extend_from_slice(&words[after_caps..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const MAGIC: u32 = 0x0723_0203;

    /// A module's logical layout in miniature: two capabilities (one of them the float
    /// atomics'), the extension, a memory model, a pointer type and variables.
    fn module(function_vars: usize) -> Vec<u32> {
        let ext = string_words(FLOAT_ATOMIC_EXTENSION);
        let mut w = vec![MAGIC, 0x0001_0500, 0, 100, 0];
        w.extend_from_slice(&[(2 << 16) | OP_CAPABILITY, 1]); // Shader
        w.extend_from_slice(&[(2 << 16) | OP_CAPABILITY, 6033]);
        w.push(((1 + ext.len() as u32) << 16) | OP_EXTENSION);
        w.extend_from_slice(&ext);
        w.extend_from_slice(&[(3 << 16) | 14, 0, 1]); // OpMemoryModel Logical GLSL450
        w.extend_from_slice(&[(4 << 16) | 32, 5, STORAGE_FUNCTION, 6]); // OpTypePointer
        for i in 0..function_vars {
            w.extend_from_slice(&[(4 << 16) | OP_VARIABLE, 5, 10 + i as u32, STORAGE_FUNCTION]);
        }
        w.extend_from_slice(&[(4 << 16) | OP_VARIABLE, 5, 9, 12]); // StorageBuffer
        w
    }

    #[test]
    fn the_extension_is_found_and_function_variables_counted() {
        let m = module(3);
        assert!(declares_extension(&m, FLOAT_ATOMIC_EXTENSION));
        assert!(!declares_extension(&m, "SPV_KHR_other"));
        assert_eq!(function_variables(&m), 3);
        assert!(!needs_reoptimising(&m));
        assert!(needs_reoptimising(&module(UNOPTIMISED_FUNCTION_VARIABLES + 1)));
    }

    #[test]
    fn hiding_and_restoring_gives_the_module_back() {
        let m = module(2);
        let (hidden, caps) = hide_extension(&m);
        assert_eq!(caps, vec![6033]);
        assert!(!declares_extension(&hidden, FLOAT_ATOMIC_EXTENSION));
        assert_eq!(hidden.len(), m.len() - 2 - 1 - string_words(FLOAT_ATOMIC_EXTENSION).len());
        assert_eq!(function_variables(&hidden), 2);
        let back = restore_extension(&hidden, &caps);
        assert_eq!(back.len(), m.len());
        assert!(declares_extension(&back, FLOAT_ATOMIC_EXTENSION));
        // Capabilities first (in any order), then the extension, then the rest unchanged.
        let ops: Vec<u32> = instructions(&back).map(|(_, op, _)| op).collect();
        assert_eq!(&ops[..4], &[OP_CAPABILITY, OP_CAPABILITY, OP_EXTENSION, 14]);
        let caps_back: Vec<u32> = instructions(&back).filter(|(_, op, _)| *op == OP_CAPABILITY).map(|(_, _, a)| a[0]).collect();
        assert_eq!(caps_back, vec![6033, 1]);
        assert_eq!(back[back.len() - 12..], m[m.len() - 12..]);
    }

    /// Every kernel of a release build went through the optimiser: none keeps the hundreds of
    /// Function-scope variables glslang writes (the float atomics' kernels neither, through
    /// build.rs's `reoptimise`). Only `abi_layout` is compiled unoptimised, on purpose.
    #[test]
    fn release_kernels_are_all_optimised() {
        if cfg!(debug_assertions) {
            eprintln!("skipped: a debug build compiles its kernels unoptimised");
            return;
        }
        let left: Vec<String> = crate::gpu::kernels::ALL
            .iter()
            .filter(|k| k.name != "abi_layout")
            .map(|k| (k.name, function_variables(&k.spirv_words())))
            .filter(|&(_, n)| n > UNOPTIMISED_FUNCTION_VARIABLES)
            .map(|(name, n)| format!("{name}: {n}"))
            .collect();
        assert!(left.is_empty(), "kernels left unoptimised (Function-scope variables): {left:?}; see build.rs's warnings");
    }

    #[test]
    fn a_name_of_a_whole_number_of_words_still_ends_in_a_nul() {
        assert_eq!(string_words("abcd"), vec![u32::from_le_bytes(*b"abcd"), 0]);
        assert_eq!(string_words("abc"), vec![u32::from_le_bytes(*b"abc\0")]);
        assert_eq!(string_words(FLOAT_ATOMIC_EXTENSION).len(), 8);
    }
}
