"""The docs' runner (tests/docs_blocks.py) fails a block whose comments misstate what it prints."""
import pytest

import docs_blocks

BLOCK = '''x = 3
print(x)                 # 3: an explanation
print([1.80083901234])   # [1.80083901...]
for f in (1.2, 0.8):
    print(f, f > 1)
# 1.2 True
# 0.8 False
print("the model")       # which model, and why
'''


def test_a_block_that_prints_what_it_says_passes():
    assert docs_blocks.run(BLOCK, "block", notes=True)["x"] == 3


@pytest.mark.parametrize("old, new", [
    ("# 3: an explanation", "# 4: an explanation"),   # a wrong value
    ("# [1.80083901...]", "# [1.80083902...]"),       # a wrong prefix
    ("# 0.8 False", "# 0.8 True"),                    # a wrong line of a loop
    ("# 0.8 False\n", ""),                            # a loop's line left unsaid
    ("x = 3\n", "x = 3\nif x < 0:\n    print(x)  # 3\n"),   # a stated output never printed
])
def test_a_block_that_misstates_its_output_fails(old, new):
    with pytest.raises(AssertionError):
        docs_blocks.run(BLOCK.replace(old, new), "block", notes=True)


def test_words_are_notes_only_where_the_page_writes_notes():
    with pytest.raises(AssertionError, match="which model"):
        docs_blocks.run(BLOCK, "block")
    assert docs_blocks.head("['lean', 'lean'] (the third: a circle)") == "['lean', 'lean']"
    assert docs_blocks.head("True ('v',)") == "True ('v',)"
    assert docs_blocks.head("{'g': 9.81}: the defaults") == "{'g': 9.81}"
