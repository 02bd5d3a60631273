//! Returning freed heap memory to the operating system.
//!
//! A subscriber that vanishes without a goodbye (a SIGKILLed rclpy script)
//! stays matched until its participant's lease expires (Cyclone DDS: 10 s);
//! meanwhile RustDDS keeps every sample it has not acknowledged, up to 8,192
//! per writer. When the lease expires those samples are freed, but glibc keeps
//! the freed pages in its per-thread arenas, so without a trim the node's
//! resident memory only ever grows with peer churn (docs/ros.md, "Memory").
//! A background thread trims the heap every [`TRIM_PERIOD`]; the simulation
//! thread is never involved.

use std::time::Duration;

/// How often the freed heap is handed back.
pub const TRIM_PERIOD: Duration = Duration::from_secs(5);

/// Hand freed heap pages back to the OS; returns whether any were released.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
pub fn trim() -> bool {
    extern "C" {
        /// glibc: release free memory at the top of the heap and, since glibc
        /// 2.8, whole free pages inside every arena (madvise(MADV_DONTNEED)).
        fn malloc_trim(pad: usize) -> std::os::raw::c_int;
    }
    // SAFETY: malloc_trim takes no pointers and is thread-safe (it locks each arena).
    unsafe { malloc_trim(0) != 0 }
}

/// Other allocators return memory by themselves.
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
pub fn trim() -> bool {
    false
}

/// Start the trimming thread; it ends with the process.
pub fn spawn_trimmer() -> std::io::Result<std::thread::JoinHandle<()>> {
    std::thread::Builder::new()
        .name("annular_plate-heap".into())
        .spawn(|| loop {
            std::thread::sleep(TRIM_PERIOD);
            trim();
        })
}
