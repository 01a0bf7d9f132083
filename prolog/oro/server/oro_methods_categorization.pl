:- module(oro_methods_categorization, []).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(oro/questions/oro_categorize)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).

/** <module> ORO methods: concept comparison

The protocol face of oro_categorize (ORO-SPEC §6.5, algorithms §10),
declared as clauses of the method table oro_methods:method/4:

  | method                                | answer                               |
  |---------------------------------------|--------------------------------------|
  | getSimilarities(String, String)       | `["? rdf:type Animal","? eats grass"]` |
  | getDifferences(String, String)        | `[["cow eats grass","gorilla eats apple"],...]` |
  | discriminate(Set)                     | `[[total...],[best...]]`             |
  | discriminateForAgent(String, Set)     | the same, in the agent's model        |

The first three ask the robot's model (`myself`).  Names are expanded
as everywhere in the protocol and contracted on the way back
(`rdf:type`, `eats`); statements are in ORO's light form
(`cow weight 150.7`).  Errors are the library's ISO errors, turned
into ORO's exceptions by oro_errors.
*/

:- multifile
    oro_methods:method/4.

oro_methods:method(getSimilarities(string, string), 'concept comparison',
                   "Returns what two individuals have in common, as partial statements (\"? eats grass\").",
                   oro_methods_categorization:m_similarities).
oro_methods:method(getDifferences(string, string), 'concept comparison',
                   "Returns what tells two individuals apart, as groups of statements.",
                   oro_methods_categorization:m_differences).
oro_methods:method(discriminate(set), 'concept comparison',
                   "Returns [total discriminants, best discriminants]: the properties that best tell the individuals apart.",
                   oro_methods_categorization:m_discriminate).
oro_methods:method(discriminateForAgent(string, set), agents,
                   "Returns [total discriminants, best discriminants] of the individuals, in the model of an agent.",
                   oro_methods_categorization:m_discriminate_for_agent).

m_similarities(IdA, IdB, list(Texts)) :-
    oro_name_iri(IdA, A),
    oro_name_iri(IdB, B),
    oro_similarities(myself, A, B, Similarities),
    maplist(similarity_text, Similarities, Texts).

similarity_text(similar(P, V), string(Text)) :-
    oro_term_light_text(P, PT),
    oro_term_light_text(V, VT),
    atomic_list_concat(['?', PT, VT], ' ', Text).

m_differences(IdA, IdB, list(Groups)) :-
    oro_name_iri(IdA, A),
    oro_name_iri(IdB, B),
    oro_differences(myself, A, B, Differences),
    maplist(group_value, Differences, Groups).

group_value(Triples, list(Texts)) :-
    maplist(statement_value, Triples, Texts).

statement_value(rdf(S, P, O), string(Text)) :-
    oro_term_light_text(S, ST),
    oro_term_light_text(P, PT),
    oro_term_light_text(O, OT),
    atomic_list_concat([ST, PT, OT], ' ', Text).

m_discriminate(Ids, Reply) :-
    discriminate(myself, Ids, Reply).

m_discriminate_for_agent(Agent, Ids, Reply) :-
    atom_string(Name, Agent),
    oro_resolve_model(Name, Model),
    discriminate(Model, Ids, Reply).

discriminate(Model, Ids, list([list(TotalNames), list(BestNames)])) :-
    maplist(oro_name_iri, Ids, Individuals),
    oro_discriminate(Model, Individuals, Total, Best),
    maplist(name_value, Total, TotalNames),
    maplist(name_value, Best, BestNames).

name_value(IRI, string(Name)) :-
    oro_iri_name(IRI, Name).
