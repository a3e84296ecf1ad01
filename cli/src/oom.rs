//! Out of memory ends a command with exit 2 and one line naming the cause, not an abort with a
//! backtrace (a 1 GB log under `ulimit -v 2000000` made `pipeline` exit 134). Stable Rust
//! cannot unwind from a failed allocation, so the allocator says so and exits itself.

use std::alloc::{GlobalAlloc, Layout, System};

/// The system allocator; a failed request writes the message and exits 2.
pub struct Graceful;

// SAFETY: every call is forwarded unchanged to `System`; only a null result is handled.
unsafe impl GlobalAlloc for Graceful {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if p.is_null() {
            out_of_memory(layout.size());
        }
        p
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if p.is_null() {
            out_of_memory(layout.size());
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if p.is_null() {
            out_of_memory(new_size);
        }
        p
    }
}

/// A fixed buffer to format into without allocating.
struct Buf {
    bytes: [u8; 256],
    len: usize,
}

impl std::fmt::Write for Buf {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let n = s.len().min(self.bytes.len() - self.len);
        self.bytes[self.len..self.len + n].copy_from_slice(&s.as_bytes()[..n]);
        self.len += n;
        Ok(())
    }
}

fn out_of_memory(size: usize) -> ! {
    use std::fmt::Write;
    let mut b = Buf { bytes: [0; 256], len: 0 };
    let mb = size as f64 / (1u64 << 20) as f64;
    let _ = writeln!(
        b,
        "gyrodrift: out of memory (a request for {mb:.0} MB failed): the log is too large for this machine's memory or its limit (ulimit -v); split it (recipe span_s) or run where more memory is free"
    );
    // SAFETY: writing a buffer we own to fd 2, then ending the process without unwinding or
    // running destructors (which could allocate again).
    unsafe {
        libc::write(2, b.bytes.as_ptr().cast(), b.len);
        libc::_exit(2)
    }
}
