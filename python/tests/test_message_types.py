"""The LCM types generated for Python read what the C++ types write, and write it back byte for
byte (so fingerprints and layouts agree), without LCM's own Python module."""

import os
import subprocess

import pytest

import lcmtf


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """The C++ encoding of one sample message per type, by type name."""
    directory = tmp_path_factory.mktemp("messages")
    subprocess.run([os.environ["LCMTF_WRITE_SAMPLE_MESSAGES"], str(directory)], check=True)
    return {path.stem: path.read_bytes() for path in directory.glob("*.bin")}


def decoded(written, message_type):
    data = written[message_type.__name__]
    message = message_type.decode(data)
    assert message.encode() == data
    return message


def test_tf_message_from_cpp_decodes_and_encodes_back(written):
    message = decoded(written, lcmtf.tf_message_t)
    assert (message.utime, message.authority, message.sequence) == (
        1700000000000001, "spy_sample@host:42", 17)
    assert [(t.parent_frame, t.child_frame) for t in message.transforms] == [
        ("world", "base_link"), ("base_link", "camera_optical")]
    first = message.transforms[0]
    assert (first.translation.x, first.translation.y, first.translation.z) == (1.5, 2.5, -3.25)
    assert (first.rotation.z, first.rotation.w) == (0.6, 0.8)


def test_the_other_types_from_cpp_decode_and_encode_back(written):
    transform = decoded(written, lcmtf.transform_t)
    assert (transform.parent_frame, transform.child_frame, transform.translation.x) == (
        "map", "odom", -7.75)
    joints = decoded(written, lcmtf.joint_state_t)
    assert joints.name == ["shoulder_pan", "elbow", "wrist_roll"]
    assert list(joints.position) == [0.5, -1.25, 3.0] and list(joints.effort) == []
    assert decoded(written, lcmtf.resend_request_t).requester == "spy_sample_requester"
    assert decoded(written, lcmtf.robot_description_t).robot_name == "spy_bot"


def test_a_message_built_in_python_round_trips():
    message = lcmtf.tf_message_t()
    message.authority = "python@host:1"
    transform = lcmtf.transform_t()
    transform.parent_frame, transform.child_frame = "map", "base"
    transform.translation.x = 4.0
    message.transforms = [transform]
    message.num_transforms = 1
    back = lcmtf.tf_message_t.decode(message.encode())
    assert back.transforms[0].child_frame == "base" and back.transforms[0].translation.x == 4.0
