:- module(oro_lookup,
          [ oro_exists/2,               % +Model, +Resource
            oro_label/3,                % +Model, +Resource, -Label
            oro_label/4,                % +Model, +Resource, +Lang, -Label
            oro_lookup/3,               % +Model, +Text, -Matches
            oro_resource_kind/3,        % +Model, +Resource, -Kind
            oro_infos/3,                % +Model, +Resource, -Triples
            oro_resource_details/4      % +Model, +Resource, +Lang, -Details
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(error)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/questions/oro_taxonomy)).

/** <module> Labels, lookup and descriptions of resources

How a robot finds what a human names: oro_lookup/3 matches a text,
case-insensitively and exactly, against the labels (any language) and
local names of individuals, and against the labels of classes and
properties (their local name when they have no label).  Descriptions of
a resource (oro_infos/3, oro_resource_details/4) are read over the
inference closure of the model.  Resources are named as in
statements: `fork1` (the default namespace), `oro:fork1` or a full
IRI.  The model is a model's name or alias
(`default`, the robot id); an unknown one raises
existence_error(agent, Model).
*/

:- setting(language, atom, en,
           'Preferred language of labels').

:- rdf_meta
    oro_exists(+, r),
    oro_label(+, r, -),
    oro_label(+, r, +, -),
    oro_resource_kind(+, r, -),
    oro_infos(+, r, -),
    oro_resource_details(+, r, +, -).

%!  oro_exists(+Model, +Resource) is semidet.
%
%   Resource appears in Model, as subject, predicate or object of a
%   visible triple, or is owl:Thing, the class of every individual,
%   which the taxonomy gives whether or not a triple names it.

oro_exists(Model0, Name) :-
    oro_resolve_model(Model0, Model),
    must_be(nonvar, Name),
    oro_resource(Name, Resource),
    exists(Model, Resource).

exists(Model, Resource) :-
    (   rdf_equal(Resource, owl:'Thing')
    ;   oro_asserted(Model, Resource, _, _)
    ;   oro_asserted(Model, _, Resource, _)
    ;   oro_asserted(Model, _, _, Resource)
    ),
    !.

%   must_exist(+Model, +Name, -Resource): Resource is the IRI of Name,
%   a resource of Model.

must_exist(Model, Name, Resource) :-
    must_be(nonvar, Name),
    oro_resource(Name, Resource),
    (   exists(Model, Resource)
    ->  true
    ;   existence_error(resource, Resource)
    ).

%!  oro_label(+Model, +Resource, -Label) is det.
%!  oro_label(+Model, +Resource, +Lang, -Label) is det.
%
%   Label is the rdfs:label of Resource in Lang (default: the
%   `language` setting, `en`), else one in a variant of Lang (`en-GB`
%   for `en`, `en` for `en-US`), else any of its labels, else its local
%   name.  Label is an atom.  Lang is an atom or a string; language
%   tags compare ignoring case (`fr` finds `"tasse"@FR`).
%
%   @error existence_error(resource, Resource) if it is unknown.

oro_label(Model, Resource, Label) :-
    setting(language, Lang),
    oro_label(Model, Resource, Lang, Label).

oro_label(Model0, Name, Lang0, Label) :-
    oro_resolve_model(Model0, Model),
    must_exist(Model, Name, Resource),
    language(Lang0, Lang),
    label(Model, Resource, Lang, Label).

%   language(+Text, -Lang): the language tag Text, lower case.

language(Text, Lang) :-
    must_be(text, Text),
    atom_string(Atom, Text),
    downcase_atom(Atom, Lang).

%   label(+Model, +Resource, +Lang, -Label): as oro_label/4, Lang a
%   language tag in lower case (language/2).

label(Model, Resource, Lang, Label) :-
    rdf_equal(rdfs:label, LabelP),
    findall(L, oro_asserted(Model, Resource, LabelP, L), Labels0),
    sort(Labels0, Labels),
    (   member(literal(lang(Tag, Text)), Labels),
        downcase_atom(Tag, Lang)
    ->  true
    ;   primary_language(Lang, Primary),
        member(literal(lang(Tag, Text)), Labels),
        primary_language(Tag, Primary)
    ->  true
    ;   member(literal(L), Labels),
        L \= lang(_, _)
    ->  oro_literal_lexical(literal(L), Text)
    ;   member(literal(L), Labels)
    ->  oro_literal_lexical(literal(L), Text)
    ;   rdf_is_bnode(Resource)
    ->  oro_iri_name(Resource, Text)
    ;   oro_local_name(Resource, Text)
    ),
    !,
    atomic_to_atom(Text, Label).

%   primary_language(+Tag, -Primary): Primary is the language subtag of
%   Tag (`en` for `en-GB`), in lower case.

primary_language(Tag, Primary) :-
    downcase_atom(Tag, Lower),
    (   sub_atom(Lower, Before, _, _, -)
    ->  sub_atom(Lower, 0, Before, _, Primary)
    ;   Primary = Lower
    ).

atomic_to_atom(Text, Atom) :-
    atom_string(Atom, Text).

%!  oro_lookup(+Model, +Text, -Matches) is det.
%
%   Matches is the ordered set of Resource-Kind pairs whose label or
%   name is Text, ignoring case.  Kind is `instance`, `class`,
%   `object_property` or `datatype_property`.  Individuals match by any
%   label and by local name; classes and properties by their labels,
%   or by their local name when they have none.

oro_lookup(Model0, Text, Matches) :-
    oro_resolve_model(Model0, Model),
    must_be(text, Text),
    atom_string(Atom, Text),
    findall(R, label_match(Model, Atom, R), ByLabel),
    findall(R, name_match(Model, Atom, R), ByName),
    append(ByLabel, ByName, Candidates0),
    sort(Candidates0, Candidates),
    findall(R-Kind,
            ( member(R, Candidates),
              resource_kind(Model, R, Kind),
              matches_as(Model, Kind, R, ByLabel)
            ),
            Matches0),
    sort(Matches0, Matches).

label_match(Model, Text, Resource) :-
    rdf_equal(rdfs:label, LabelP),
    rdf(Resource, LabelP, literal(exact(Text), Value)),
    atom(Resource),
    \+ rdf_is_bnode(Resource),
    once(oro_asserted(Model, Resource, LabelP, literal(Value))).

%   Local names: the resources of the store whose local name is Text,
%   ignoring case, found through the store's name index.

name_match(Model, Text, Resource) :-
    downcase_atom(Text, Lower),
    oro_named(Lower, Resource),
    exists(Model, Resource).

matches_as(_, instance, _, _) :-
    !.
matches_as(Model, _, Resource, ByLabel) :-
    (   memberchk(Resource, ByLabel)
    ->  true
    ;   rdf_equal(rdfs:label, LabelP),
        \+ oro_asserted(Model, Resource, LabelP, _)
    ).

%!  oro_resource_kind(+Model, +Resource, -Kind) is nondet.
%
%   Resource is of Kind in Model: `instance`, `class`,
%   `object_property` or `datatype_property`.

oro_resource_kind(Model0, Name, Kind) :-
    oro_resolve_model(Model0, Model),
    must_be(nonvar, Name),
    oro_resource(Name, Resource),
    resource_kind(Model, Resource, Kind).

resource_kind(Model, Resource, Kind) :-
    (   oro_individual(Model, Resource),
        Kind = instance
    ;   oro_class(Model, Resource),
        Kind = class
    ;   oro_property(Model, Resource, PKind),
        property_kind(PKind, Kind)
    ).

property_kind(object, object_property).
property_kind(datatype, datatype_property).

%!  oro_infos(+Model, +Resource, -Triples) is det.
%
%   Triples are the rdf(Resource, P, O) of the inference closure of
%   Model: what is known about Resource as a subject.
%
%   @error existence_error(resource, Resource) if it is unknown.

oro_infos(Model0, Name, Triples) :-
    oro_resolve_model(Model0, Model),
    must_exist(Model, Name, Resource),
    findall(rdf(Resource, P, O), oro_holds(Model, Resource, P, O), Triples).

%!  oro_resource_details(+Model, +Resource, +Lang, -Details) is det.
%
%   Details describes Resource for a user interface, as a dict:
%
%     - name: its label in Lang; id: the resource;
%     - type: `class`, `instance`, `object_property`,
%       `datatype_property` or `undefined` (`class` for a class that
%       is also an individual);
%     - same_as: equivalent classes or owl:sameAs individuals;
%     - attributes: for a class, its direct super-classes,
%       sub-classes and instances; for an individual, its direct
%       classes then its property values, each as
%       attribute(Name, Id, Values) with Values a list of
%       value(Label, IdOrLiteral).
%
%   @error existence_error(resource, Resource) if it is unknown.

oro_resource_details(Model0, Resource0, Lang0, Details) :-
    oro_resolve_model(Model0, Model),
    must_exist(Model, Resource0, Resource),
    language(Lang0, Lang),
    label(Model, Resource, Lang, Name),
    details_kind(Model, Resource, Kind),
    same_as(Model, Kind, Resource, SameAs),
    attributes(Model, Kind, Resource, Lang, Attributes),
    Details = _{name:Name, id:Resource, type:Kind,
                same_as:SameAs, attributes:Attributes}.

%   details_kind(+Model, +Resource, -Kind): the kind Resource is
%   described as.  A class that is also an individual (punning) is
%   described as a class, as the taxonomy and the categorization treat
%   it.

details_kind(Model, Resource, Kind) :-
    (   resource_kind(Model, Resource, class)
    ->  Kind = class
    ;   resource_kind(Model, Resource, Kind0)
    ->  Kind = Kind0
    ;   Kind = undefined
    ).

same_as(Model, class, Class, Same) :-
    !,
    findall(C, ( oro_subclass(Model, Class, C),
                 C \== Class,
                 \+ rdf_is_bnode(C),
                 oro_subclass(Model, C, Class)
               ), Same0),
    sort(Same0, Same).
same_as(Model, instance, X, Same) :-
    !,
    findall(Y, ( oro_same_individual(Model, X, Y), Y \== X ), Same0),
    sort(Same0, Same).
same_as(_, _, _, []).

attributes(Model, class, Class, Lang,
           [ attribute('Parents', superClasses, Supers),
             attribute('Children', subClasses, Subs),
             attribute('Instances', instances, Instances)
           ]) :-
    !,
    oro_direct_superclasses(Model, Class, S),
    oro_direct_subclasses(Model, Class, C),
    oro_direct_instances(Model, Class, I),
    maplist(resource_value(Model, Lang), S, Supers),
    maplist(resource_value(Model, Lang), C, Subs),
    maplist(resource_value(Model, Lang), I, Instances).
attributes(Model, instance, X, Lang,
           [attribute('Classes', classes, Classes)|Properties]) :-
    !,
    oro_direct_classes_of(Model, X, Cs),
    maplist(resource_value(Model, Lang), Cs, Classes),
    findall(P-O, ( oro_holds(Model, X, P, O),
                   \+ hidden_property(P)
                 ), Pairs0),
    sort(Pairs0, Pairs),
    group_values(Pairs, Model, Lang, Properties).
attributes(_, _, _, _, []).

:- rdf_meta hidden_property(r).

hidden_property(rdf:type).
hidden_property(owl:sameAs).
hidden_property(owl:differentFrom).
hidden_property(owl:topDataProperty).
hidden_property(owl:bottomDataProperty).
hidden_property(rdfs:label).

group_values([], _, _, []).
group_values([P-O|T], Model, Lang, [attribute(Name, properties, Values)|Rest]) :-
    oro_local_name(P, Name),
    same_key(P, T, Os, T1),
    maplist(object_value(Model, Lang), [O|Os], Values),
    group_values(T1, Model, Lang, Rest).

same_key(P, [P-O|T], [O|Os], Rest) :-
    !,
    same_key(P, T, Os, Rest).
same_key(_, Rest, [], Rest).

resource_value(Model, Lang, R, value(Label, R)) :-
    label(Model, R, Lang, Label).

object_value(_, _, literal(L), value(Text, literal)) :-
    !,
    oro_literal_lexical(literal(L), Text).
object_value(Model, Lang, R, Value) :-
    resource_value(Model, Lang, R, Value).
