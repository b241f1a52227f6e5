"""Registry of the generated model modules.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive); SymPy 1.14.0.
"""

#: (model, fidelity) -> module name inside this package
MODULES = {
    ('celt', 'amplitude'): 'celt_amplitude',
    ('celt', 'full'): 'celt_full',
    ('celt', 'reduced'): 'celt_reduced',
    ('chaplygin_sleigh', 'full'): 'chaplygin_sleigh_full',
    ('rolling_disk', 'full'): 'rolling_disk_full',
    ('rolling_disk_damped', 'full'): 'rolling_disk_damped_full',
    ('single_mode', 'amplitude'): 'single_mode_amplitude',
    ('single_mode', 'full'): 'single_mode_full',
    ('single_mode', 'reduced'): 'single_mode_reduced',
    ('two_mode', 'amplitude'): 'two_mode_amplitude',
    ('two_mode', 'full'): 'two_mode_full',
    ('two_mode', 'reduced'): 'two_mode_reduced',
    ('two_mode_rigid', 'full'): 'two_mode_rigid_full',
}
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '7fc18b0f4714471765b220e8fba854143fd64e83ba7c0b76a026fee060da44ec'
