//! Gives the shared library a versioned SONAME on ELF platforms (docs/install.md): the default
//! build is `libinterfacial.so.<ABI>`, the CalculiX variant `libinterfacial_calculix.so.<ABI>`,
//! so a host linked against one never loads the other by accident. CMake installs the file as
//! `lib….so.<version>` with the `lib….so.<ABI>` and `lib….so` links.

/// The C ABI version: the number in the SONAME. It changes only when an exported function or
/// type changes incompatibly (CHANGELOG.md, "C ABI"); CMakeLists.txt's
/// `INTERFACIAL_SOVERSION` must be the same number (the consumer suite checks the SONAME it
/// installs).
const ABI_VERSION: u32 = 0;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let elf = matches!(
        os.as_str(),
        "linux" | "freebsd" | "netbsd" | "openbsd" | "dragonfly" | "solaris" | "illumos"
    );
    if !elf {
        return;
    }
    let stem = if std::env::var_os("CARGO_FEATURE_CALCULIX").is_some() {
        "libinterfacial_calculix"
    } else {
        "libinterfacial"
    };
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{stem}.so.{ABI_VERSION}");
}
