#include "tessera/assets/GltfLoader.h"

#include "AnimationConverter.h"
#include "GltfDocument.h"
#include "GltfError.h"
#include "LodReader.h"
#include "MeshConverter.h"
#include "TextureDecoder.h"
#include "tessera/character/FarMesh.h"

#include <new>

namespace tessera::assets {

Result<character::CharacterAsset> loadCharacter(const std::filesystem::path& file) {
    // The path as the user gave it, so the message says which file.
    const std::string name = file.string();
    try {
        GltfDocument document = GltfDocument::load(file);
        const tinygltf::Model& model = document.model();
        SkeletonBuild skeleton = buildSkeleton(model);
        MeshConverter meshes(model, skeleton);
        character::CharacterAsset asset;
        asset.cage = meshes.convert();
        asset.farMesh = readFarLod(model, document.json(), skeleton, asset.cage);
        if (!asset.farMesh) {
            // No far level in the file (any glTF but the generated
            // creatures): make it now, as tessera-creaturegen would have.
            Result<character::FarMesh> far = character::simplifyCage(asset.cage);
            if (!far) return Error{name + ": " + far.error().message};
            asset.farMesh = std::move(far.value().mesh);
        }
        asset.clips = convertAnimations(model, skeleton);
        asset.skeleton = std::move(skeleton.skeleton);
        decodeMaterialTextures(model, document.json(), meshes.firstMaterial(), asset);
        asset.name = file.stem().string();
        asset.source = file.string();
        return asset;
    } catch (const GltfError& e) {
        return Error{name + ": " + e.what()};
    } catch (const nlohmann::json::exception& e) {
        // A JSON type the validators did not anticipate: still bad input, never a crash.
        return Error{name + ": malformed glTF JSON (" + e.what() + ")"};
    } catch (const std::bad_alloc&) {
        return Error{name + ": out of memory while loading"};
    }
}

} // namespace tessera::assets
