//! The release binary carries no DWARF debug info (with `debug = 1` it is
//! 87–92 MB; `cargo build --profile profiling` keeps line tables for
//! perf). Read from the ELF section headers of the binary the tests run.

use std::path::Path;

fn u16_at(b: &[u8], at: usize) -> usize {
    u16::from_le_bytes(b[at..at + 2].try_into().unwrap()) as usize
}

fn u32_at(b: &[u8], at: usize) -> usize {
    u32::from_le_bytes(b[at..at + 4].try_into().unwrap()) as usize
}

fn u64_at(b: &[u8], at: usize) -> usize {
    u64::from_le_bytes(b[at..at + 8].try_into().unwrap()) as usize
}

/// Section names of a little-endian ELF64 file.
fn section_names(elf: &[u8]) -> Vec<String> {
    assert_eq!(&elf[..4], b"\x7fELF", "not an ELF file");
    assert_eq!((elf[4], elf[5]), (2, 1), "ELF64 little-endian expected");
    let (shoff, shentsize, shnum, shstrndx) = (
        u64_at(elf, 0x28),
        u16_at(elf, 0x3A),
        u16_at(elf, 0x3C),
        u16_at(elf, 0x3E),
    );
    let header = |i: usize| shoff + i * shentsize;
    let strtab = u64_at(elf, header(shstrndx) + 0x18);
    (0..shnum)
        .map(|i| {
            let start = strtab + u32_at(elf, header(i));
            let end = start + elf[start..].iter().position(|&c| c == 0).unwrap();
            String::from_utf8_lossy(&elf[start..end]).into_owned()
        })
        .collect()
}

// A debug build's binary is not the one the README ships: there the test is
// reported as ignored, with the reason, not passed (CI runs `--release`).
#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "reads the release binary: run with `cargo test --release`"
)]
fn the_release_binary_has_no_debug_sections() {
    let bin = Path::new(env!("CARGO_BIN_EXE_annular_plate"));
    let elf = std::fs::read(bin).expect("the binary");
    let names = section_names(&elf);
    assert!(
        names.iter().any(|n| n == ".text"),
        "section table read: {names:?}"
    );
    let debug: Vec<_> = names.iter().filter(|n| n.starts_with(".debug_")).collect();
    assert!(
        debug.is_empty(),
        "debug sections in {}: {debug:?}",
        bin.display()
    );
    assert!(
        elf.len() < 40 << 20,
        "{} is {} bytes",
        bin.display(),
        elf.len()
    );
}
