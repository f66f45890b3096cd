//! A small SPIR-V reader: enough to derive a kernel's descriptor-set layout, push-constant
//! size and workgroup size from its binary (so binding tables are never written twice), and
//! to read the std430 layout the GLSL compiler chose for a struct (the ABI test).

use ash::vk;
use std::collections::HashMap;

const MAGIC: u32 = 0x0723_0203;

// Opcodes (SPIR-V spec, section 3.49).
const OP_NAME: u32 = 5;
const OP_MEMBER_NAME: u32 = 6;
const OP_EXECUTION_MODE: u32 = 16;
const OP_TYPE_INT: u32 = 21;
const OP_TYPE_FLOAT: u32 = 22;
const OP_TYPE_VECTOR: u32 = 23;
const OP_TYPE_MATRIX: u32 = 24;
const OP_TYPE_IMAGE: u32 = 25;
const OP_TYPE_SAMPLER: u32 = 26;
const OP_TYPE_SAMPLED_IMAGE: u32 = 27;
const OP_TYPE_ARRAY: u32 = 28;
const OP_TYPE_RUNTIME_ARRAY: u32 = 29;
const OP_TYPE_STRUCT: u32 = 30;
const OP_TYPE_POINTER: u32 = 32;
const OP_CONSTANT: u32 = 43;
const OP_VARIABLE: u32 = 59;
const OP_DECORATE: u32 = 71;
const OP_MEMBER_DECORATE: u32 = 72;

// Decorations (3.20), storage classes (3.7), execution modes (3.6).
const DEC_BLOCK: u32 = 2;
const DEC_BUFFER_BLOCK: u32 = 3;
const DEC_ARRAY_STRIDE: u32 = 6;
const DEC_MATRIX_STRIDE: u32 = 7;
const DEC_BINDING: u32 = 33;
const DEC_DESCRIPTOR_SET: u32 = 34;
const DEC_OFFSET: u32 = 35;
const SC_UNIFORM_CONSTANT: u32 = 0;
const SC_UNIFORM: u32 = 2;
const SC_PUSH_CONSTANT: u32 = 9;
const SC_STORAGE_BUFFER: u32 = 12;
const EM_LOCAL_SIZE: u32 = 17;

#[derive(Clone, Debug)]
enum Type {
    Scalar { bytes: u32 },
    Vector { elem: u32, count: u32 },
    Matrix { count: u32 },
    Image { sampled: u32 },
    Sampler,
    SampledImage,
    Array { elem: u32, length_id: u32 },
    RuntimeArray { elem: u32 },
    Struct { members: Vec<u32> },
    Pointer { pointee: u32 },
}

/// One descriptor binding a kernel uses (set 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReflectedBinding {
    pub binding: u32,
    pub descriptor_type: vk::DescriptorType,
    pub count: u32,
}

/// A member of a struct as laid out in SPIR-V.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MemberLayout {
    pub name: String,
    pub offset: u32,
}

/// A parsed SPIR-V module.
#[derive(Debug, Default)]
pub struct Module {
    names: HashMap<u32, String>,
    member_names: HashMap<(u32, u32), String>,
    decorations: HashMap<(u32, u32), Vec<u32>>,
    member_decorations: HashMap<(u32, u32, u32), Vec<u32>>,
    types: HashMap<u32, Type>,
    constants: HashMap<u32, u32>,
    variables: Vec<(u32, u32, u32)>, // (pointer type, id, storage class)
    local_size: Option<[u32; 3]>,
}

fn string_at(words: &[u32]) -> String {
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).take_while(|&b| b != 0).collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

impl Module {
    /// Parses a SPIR-V binary; `Err` says what is malformed.
    pub fn parse(words: &[u32]) -> Result<Self, String> {
        if words.len() < 5 || words[0] != MAGIC {
            return Err("not a SPIR-V module (bad magic number)".into());
        }
        let mut m = Module::default();
        let mut i = 5;
        while i < words.len() {
            let count = (words[i] >> 16) as usize;
            let op = words[i] & 0xffff;
            if count == 0 || i + count > words.len() {
                return Err(format!("truncated instruction at word {i}"));
            }
            let a = &words[i + 1..i + count];
            match op {
                OP_NAME => {
                    m.names.insert(a[0], string_at(&a[1..]));
                }
                OP_MEMBER_NAME => {
                    m.member_names.insert((a[0], a[1]), string_at(&a[2..]));
                }
                OP_EXECUTION_MODE if a[1] == EM_LOCAL_SIZE => m.local_size = Some([a[2], a[3], a[4]]),
                OP_TYPE_INT | OP_TYPE_FLOAT => {
                    m.types.insert(a[0], Type::Scalar { bytes: a[1] / 8 });
                }
                OP_TYPE_VECTOR => {
                    m.types.insert(a[0], Type::Vector { elem: a[1], count: a[2] });
                }
                OP_TYPE_MATRIX => {
                    m.types.insert(a[0], Type::Matrix { count: a[2] });
                }
                OP_TYPE_IMAGE => {
                    m.types.insert(a[0], Type::Image { sampled: a[6] });
                }
                OP_TYPE_SAMPLER => {
                    m.types.insert(a[0], Type::Sampler);
                }
                OP_TYPE_SAMPLED_IMAGE => {
                    m.types.insert(a[0], Type::SampledImage);
                }
                OP_TYPE_ARRAY => {
                    m.types.insert(a[0], Type::Array { elem: a[1], length_id: a[2] });
                }
                OP_TYPE_RUNTIME_ARRAY => {
                    m.types.insert(a[0], Type::RuntimeArray { elem: a[1] });
                }
                OP_TYPE_STRUCT => {
                    m.types.insert(a[0], Type::Struct { members: a[1..].to_vec() });
                }
                OP_TYPE_POINTER => {
                    m.types.insert(a[0], Type::Pointer { pointee: a[2] });
                }
                OP_CONSTANT if a.len() >= 3 => {
                    m.constants.insert(a[1], a[2]);
                }
                OP_VARIABLE => m.variables.push((a[0], a[1], a[2])),
                OP_DECORATE => {
                    m.decorations.insert((a[0], a[1]), a[2..].to_vec());
                }
                OP_MEMBER_DECORATE => {
                    m.member_decorations.insert((a[0], a[1], a[2]), a[3..].to_vec());
                }
                _ => {}
            }
            i += count;
        }
        Ok(m)
    }

    fn decoration(&self, id: u32, dec: u32) -> Option<u32> {
        self.decorations.get(&(id, dec)).map(|v| v.first().copied().unwrap_or(0))
    }

    /// The workgroup size from `layout(local_size_x = ...)`, if given as literals.
    pub fn local_size(&self) -> Option<[u32; 3]> {
        self.local_size
    }

    /// Descriptor bindings of set 0, sorted by binding, each once (a kernel may view one buffer
    /// as arrays of several types, each a variable of its own at the same binding); `Err` for a
    /// set other than 0, a resource type bidir does not bind, or variables of one binding whose
    /// descriptors differ.
    pub fn bindings(&self) -> Result<Vec<ReflectedBinding>, String> {
        let mut out = Vec::new();
        for &(ptr, id, storage) in &self.variables {
            let Some(binding) = self.decoration(id, DEC_BINDING) else { continue };
            let set = self.decoration(id, DEC_DESCRIPTOR_SET).unwrap_or(0);
            let name = self.names.get(&id).cloned().unwrap_or_default();
            if set != 0 {
                return Err(format!("'{name}' uses descriptor set {set}; bidir kernels use set 0 only"));
            }
            let Some(Type::Pointer { pointee, .. }) = self.types.get(&ptr) else { continue };
            let (mut ty, mut count) = (*pointee, 1u32);
            if let Some(Type::Array { elem, length_id }) = self.types.get(&ty) {
                count = self.constants.get(length_id).copied().unwrap_or(1);
                ty = *elem;
            }
            let descriptor_type = match (storage, self.types.get(&ty)) {
                (SC_STORAGE_BUFFER, _) => vk::DescriptorType::STORAGE_BUFFER,
                (SC_UNIFORM, _) if self.decorations.contains_key(&(ty, DEC_BUFFER_BLOCK)) => vk::DescriptorType::STORAGE_BUFFER,
                (SC_UNIFORM, _) if self.decorations.contains_key(&(ty, DEC_BLOCK)) => vk::DescriptorType::UNIFORM_BUFFER,
                (SC_UNIFORM_CONSTANT, Some(Type::Image { sampled: 2 })) => vk::DescriptorType::STORAGE_IMAGE,
                (SC_UNIFORM_CONSTANT, Some(Type::Image { sampled: 1 })) => vk::DescriptorType::SAMPLED_IMAGE,
                (SC_UNIFORM_CONSTANT, Some(Type::SampledImage)) => vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
                (SC_UNIFORM_CONSTANT, Some(Type::Sampler)) => vk::DescriptorType::SAMPLER,
                _ => return Err(format!("'{name}' (binding {binding}) is a resource type bidir does not bind")),
            };
            out.push(ReflectedBinding { binding, descriptor_type, count });
        }
        out.sort_by_key(|b| b.binding);
        if let Some(w) = out.windows(2).find(|w| w[0].binding == w[1].binding && w[0] != w[1]) {
            return Err(format!("binding {} is declared as two kinds of descriptor: {:?} and {:?}", w[0].binding, w[0], w[1]));
        }
        out.dedup();
        Ok(out)
    }

    /// Size in bytes of the push-constant block, 0 if the kernel has none.
    pub fn push_constant_size(&self) -> u32 {
        self.variables
            .iter()
            .filter(|v| v.2 == SC_PUSH_CONSTANT)
            .filter_map(|&(ptr, _, _)| match self.types.get(&ptr) {
                Some(Type::Pointer { pointee, .. }) => self.size_of(*pointee),
                _ => None,
            })
            .max()
            .unwrap_or(0)
    }

    /// Size of a type as laid out in memory (explicit layout), if it can be known.
    fn size_of(&self, ty: u32) -> Option<u32> {
        match self.types.get(&ty)? {
            Type::Scalar { bytes } => Some(*bytes),
            Type::Vector { elem, count } => Some(self.size_of(*elem)? * count),
            // A bare matrix's stride lives on the enclosing struct member (handled there).
            Type::Matrix { .. } => None,
            Type::Array { length_id, .. } => Some(self.decoration(ty, DEC_ARRAY_STRIDE)? * self.constants.get(length_id)?),
            Type::Struct { members } => {
                let last = members.len().checked_sub(1)? as u32;
                let off = self.member_decorations.get(&(ty, last, DEC_OFFSET))?[0];
                let last_ty = members[last as usize];
                let size = match self.types.get(&last_ty)? {
                    Type::Matrix { count, .. } => self.member_decorations.get(&(ty, last, DEC_MATRIX_STRIDE))?[0] * count,
                    _ => self.size_of(last_ty)?,
                };
                Some(off + size)
            }
            _ => None,
        }
    }

    /// Finds the struct named `name` and returns its members' names and offsets, and the
    /// `ArrayStride` of a runtime array of it if the module declares one.
    pub fn struct_layout(&self, name: &str) -> Option<(Vec<MemberLayout>, Option<u32>)> {
        let (&id, members) = self.types.iter().find_map(|(id, t)| match t {
            Type::Struct { members } if self.names.get(id).map(String::as_str) == Some(name) => Some((id, members)),
            _ => None,
        })?;
        let layout = (0..members.len() as u32)
            .map(|m| MemberLayout {
                name: self.member_names.get(&(id, m)).cloned().unwrap_or_default(),
                offset: self.member_decorations.get(&(id, m, DEC_OFFSET)).map(|v| v[0]).unwrap_or(u32::MAX),
            })
            .collect();
        let stride = self.types.iter().find_map(|(aid, t)| match t {
            Type::RuntimeArray { elem } if *elem == id => self.decoration(*aid, DEC_ARRAY_STRIDE),
            _ => None,
        });
        Some((layout, stride))
    }
}
