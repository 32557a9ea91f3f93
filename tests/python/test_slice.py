"""contain.slice_mesh, contain.shadow and contain.mesh_section: sections of solids as Regions."""

import subprocess

import numpy as np
import pytest

import contain
from meshes import cube, torus


def stacked_cubes():
    """Two unit cubes stacked along z in one mesh, touching along the face z = 1."""
    one = cube()
    vertices = np.concatenate([one.vertices, one.vertices + [0, 0, 1]])
    faces = np.concatenate([one.faces, one.faces + 8])
    return contain.Mesh(vertices, faces)


def test_sections_of_a_cube_are_its_square_and_empty_at_its_faces():
    sections = contain.slice_mesh(cube(), [0.5, 0.0, 1.0, 2.0])
    assert [s.area for s in sections] == [1.0, 0.0, 0.0, 0.0]
    assert all(isinstance(s, contain.Region) for s in sections)


def test_stacked_cubes_cut_at_the_shared_face_give_the_square():
    (section,) = contain.slice_mesh(stacked_cubes(), [1.0])
    assert section.area == 1.0


def test_a_torus_cut_through_its_axis_plane_is_an_annulus_and_across_the_hole_two_discs():
    mesh = torus(1.0, 0.4, 48, 24)
    (annulus,) = contain.slice_mesh(mesh, 0.0)
    assert len(annulus.polygons) == 1 and len(annulus.polygons[0]) == 2
    (discs,) = contain.slice_mesh(mesh, [0.0], axis="x")
    assert len(discs.polygons) == 2


def test_triangles_name_a_mesh_triangle_for_every_edge_and_threads_do_not_change_answers():
    mesh = torus(1.0, 0.4, 24, 12)
    values = np.linspace(-0.35, 0.35, 15)
    pairs = contain.slice_mesh(mesh, values, axis="y", with_triangles=True, threads=1)
    again = contain.slice_mesh(mesh, values, axis="y", with_triangles=True, threads=2)
    for (region, triangles), (region2, triangles2) in zip(pairs, again):
        assert region.to_wkt() == region2.to_wkt() and triangles == triangles2
        rings = [ring for polygon in region.polygons for ring in polygon]
        assert [len(t) for t in triangles] == [len(ring) for ring in rings]
        assert all(0 <= t < len(mesh.faces) for ring in triangles for t in ring)


def test_the_command_gives_the_same_sections(tmp_path, cli):
    path = tmp_path / "torus.off"
    mesh = torus(1.0, 0.4, 24, 12)
    path.write_bytes(contain.format_mesh(mesh, "off"))
    out = subprocess.run([cli, "slice", "--mesh", str(path), "--z", "0.1", "--z", "-0.2"],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    regions = contain.slice_mesh(mesh, [0.1, -0.2])
    assert [contain.Region.from_wkt(line.split("\t")[1]).to_wkt() for line in out] == [
        r.to_wkt() for r in regions]


def test_shadow_of_a_torus_is_an_annulus_and_of_a_box_its_face():
    ring = contain.shadow(torus(1.0, 0.4, 48, 24))
    assert len(ring.polygons) == 1 and len(ring.polygons[0]) == 2
    assert contain.shadow(cube(), axis="x").area == 1.0


def test_open_meshes_and_bad_values_raise_but_open_meshes_cast_shadows():
    open_mesh = (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 2]]))
    with pytest.raises(contain.ContainError, match="not closed"):
        contain.slice_mesh(open_mesh, [0.0])
    # A shadow needs no solid: the union of the projected triangles.
    assert contain.shadow(open_mesh).area == 0.5
    with pytest.raises(contain.ContainError):
        contain.slice_mesh(cube(), [float("nan")])
    with pytest.raises(ValueError, match="axis"):
        contain.slice_mesh(cube(), [0.5], axis="w")
    with pytest.raises(TypeError):
        contain.slice_mesh(cube(), [[0.5]])


def test_mesh_section_gives_segments_of_any_mesh_and_plane():
    segments = contain.mesh_section(cube(), (0, 0, 1, -0.5))
    assert segments.shape[1:] == (2, 3)
    assert np.all(segments[:, :, 2] == 0.5)
    # The loop around the cube at half height is 4 long.
    assert np.isclose(np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1).sum(), 4.0)
    tilted = contain.mesh_section(cube(), (1, 1, 1, -1.5))
    assert len(tilted) >= 6
    open_mesh = (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 2]]))
    assert contain.mesh_section(open_mesh, (1, 0, 0, -0.5)).shape == (1, 2, 3)
