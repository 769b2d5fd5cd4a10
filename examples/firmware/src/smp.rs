//! Work for a second core (feature `smp`, RISC-V `virt -smp 2`): hart 0 posts a closure,
//! hart 1 runs it; no atomic read-modify-write (RV32IMC has none), only aligned word
//! stores and loads with fences, each word written by one hart. On Arm (one core) the
//! second closure runs after the first.

#[cfg(target_arch = "riscv32")]
use core::ptr::{addr_of, addr_of_mut, read_volatile, write_volatile};
#[cfg(target_arch = "riscv32")]
use core::sync::atomic::{fence, Ordering};

/// Address of the `&mut dyn FnMut()` hart 1 is to run; written by hart 0.
#[cfg(target_arch = "riscv32")]
static mut JOB: usize = 0;
/// Jobs posted; written by hart 0 after [`JOB`].
#[cfg(target_arch = "riscv32")]
static mut POSTED: u32 = 0;
/// Jobs hart 1 has finished; written by hart 1.
#[cfg(target_arch = "riscv32")]
static mut DONE: u32 = 0;

/// Runs `here` on this core and `there` on the second, and returns when both are done.
pub fn both(here: &mut dyn FnMut(), there: &mut dyn FnMut()) {
    #[cfg(target_arch = "riscv32")]
    // SAFETY: `job` outlives hart 1's use of it: this function waits for DONE to move on
    // before returning; JOB is written only here and DONE only by hart 1.
    unsafe {
        let mut job: &mut dyn FnMut() = there;
        let posted = read_volatile(addr_of!(POSTED)).wrapping_add(1);
        write_volatile(
            addr_of_mut!(JOB),
            &mut job as *mut &mut dyn FnMut() as usize,
        );
        fence(Ordering::SeqCst);
        write_volatile(addr_of_mut!(POSTED), posted);
        here();
        while read_volatile(addr_of!(DONE)) != posted {}
        fence(Ordering::SeqCst);
    }
    #[cfg(not(target_arch = "riscv32"))]
    {
        here();
        there();
    }
}

/// Hart 1's loop: runs each job posted, once, and says so in [`DONE`].
#[cfg(target_arch = "riscv32")]
pub extern "C" fn hart1() -> ! {
    loop {
        // SAFETY: see `both`.
        unsafe {
            let posted = read_volatile(addr_of!(POSTED));
            if posted != read_volatile(addr_of!(DONE)) {
                fence(Ordering::SeqCst);
                let f = &mut *(read_volatile(addr_of!(JOB)) as *mut &mut dyn FnMut());
                f();
                fence(Ordering::SeqCst);
                write_volatile(addr_of_mut!(DONE), posted);
            }
        }
    }
}
